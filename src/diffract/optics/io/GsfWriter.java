package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.ImageFiles;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Writes a height field as a Gwyddion Simple Field (http://gwyddion.net/documentation/user-guide-en/gsf.html):
 * the text header, NUL padding to a multiple of 4 bytes (at least one NUL), then little-endian float32 heights
 * in metres, row by row. Sizes go into XReal/YReal in metres, so the file carries its own pixel size.
 */
public final class GsfWriter {
    private GsfWriter() {
    }

    public static void write(Path file, HeightField field) throws IOException {
        String header = String.format(Locale.ROOT,
                "Gwyddion Simple Field 1.0\nXRes = %d\nYRes = %d\nXReal = %.9e\nYReal = %.9e\nXYUnits = m\nZUnits = m\n"
                        + "Title = written by diffract\n",
                field.cols(), field.rows(), field.widthUm() * 1e-6, field.heightExtentUm() * 1e-6);
        byte[] text = header.getBytes(StandardCharsets.UTF_8);
        int padding = 4 - (text.length % 4); // 1..4 NULs
        ByteBuffer data = ByteBuffer.allocate(text.length + padding + 4 * field.sampleCount()).order(ByteOrder.LITTLE_ENDIAN);
        data.put(text);
        data.put(new byte[padding]);
        for (int r = 0; r < field.rows(); r++) {
            for (int c = 0; c < field.cols(); c++) {
                data.putFloat((float) (field.heightUm(r, c) * 1e-6));
            }
        }
        ImageFiles.writeAtomically(file, out -> out.write(data.array()));
    }
}
