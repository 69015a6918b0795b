package diffract.app;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

import java.nio.file.Path;

/**
 * {@code --tile I/N --pieces DIR}: a run computes only band I of N bands of the map's rows and leaves it, as one piece
 * file and its manifest, in a folder that {@code diffract merge} turns into the map. A long reference map can so be
 * split over processes or machines; {@code diffract submit} does it on this one.
 */
final class TileOptions {
    @Option(names = "--tile", paramLabel = "I/N", converter = Tile.Converter.class,
            description = "Compute only band I (0..N-1) of N equal bands of the map's rows, as floats, into "
                    + "--pieces DIR; 'diffract merge DIR -o MAP.png' writes the map (CPU only, no -o, --pfm, --exr).")
    Tile tile;

    @Option(names = "--pieces", paramLabel = "DIR",
            description = "With --tile: the folder the piece and its manifest go to (made if missing).")
    Path pieces;

    /** Band {@code index} of {@code count}. */
    record Tile(int index, int count) {
        /** The file names of this piece: {@code piece-I-of-N} and an extension. */
        String fileName(String extension) {
            return "piece-" + index + "-of-" + count + extension;
        }

        @Override
        public String toString() {
            return index + "/" + count;
        }

        static final class Converter implements ITypeConverter<Tile> {
            @Override
            public Tile convert(String text) {
                String[] parts = text.trim().split("/", -1);
                try {
                    if (parts.length == 2) {
                        int index = Integer.parseInt(parts[0].trim());
                        int count = Integer.parseInt(parts[1].trim());
                        if (count >= 1 && index >= 0 && index < count) {
                            return new Tile(index, count);
                        }
                    }
                } catch (NumberFormatException e) {
                    // falls through to the one message below
                }
                throw new TypeConversionException("must be I/N with 0 <= I < N (band I of N bands of rows), got '"
                        + text + "'");
            }
        }
    }
}
