package diffract.app.options;

import diffract.jrtr.contexts.HeadlessGL;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

import java.util.List;

/** {@code --gpu N}: which EGL device the offscreen OpenGL of a command runs on (docs/guide/headless-gl.md). */
public final class GpuOption {
    private Integer index;

    @Option(names = "--gpu", paramLabel = "N", converter = DeviceIndex.class)
    void setGpu(int index) {
        HeadlessGL.useGpu(index);
        this.index = index;
    }

    /** The option as given, for a command that runs another: {@code --gpu N}, or nothing. */
    public List<String> arguments() {
        return index == null ? List.of() : List.of("--gpu", Integer.toString(index));
    }

    /** A device index: a whole number from 0. */
    static final class DeviceIndex implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            try {
                int value = Integer.parseInt(text.trim());
                if (value >= 0) {
                    return value;
                }
            } catch (NumberFormatException e) {
                // the message below
            }
            throw new TypeConversionException("must be a device index 0, 1, ..., got '" + text + "'");
        }
    }
}
