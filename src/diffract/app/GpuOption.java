package diffract.app;

import diffract.jrtr.HeadlessGL;
import picocli.CommandLine.Option;

import java.util.List;

/** {@code --gpu N}: which EGL device the offscreen OpenGL of a command runs on (docs/headless-gl.md). */
final class GpuOption {
    private Integer index;

    @Option(names = "--gpu", paramLabel = "N",
            description = "Render on EGL device N (0, 1, ...; default: the environment's " + HeadlessGL.GPU_VARIABLE
                    + ", else the first GPU, else Mesa's software rasteriser).")
    void setGpu(int index) {
        HeadlessGL.useGpu(index);
        this.index = index;
    }

    /** The option as given, for a command that runs another: {@code --gpu N}, or nothing. */
    List<String> arguments() {
        return index == null ? List.of() : List.of("--gpu", Integer.toString(index));
    }
}
