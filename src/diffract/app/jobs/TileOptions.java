package diffract.app.jobs;

import diffract.util.OutputPaths;
import diffract.util.UserInputException;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code --tile I/N --pieces DIR}: a run computes only piece I of N equal pieces of its result (a BRDF map's rows, a
 * turntable's frames, a bench sweep's configurations) and leaves it, as one piece file and its manifest, in a folder that {@code diffract merge}
 * turns into the result. Long work can so be split over processes or machines; {@code diffract submit} does it on
 * this one or on a Slurm cluster.
 */
public final class TileOptions {
    @Option(names = "--tile", paramLabel = "I/N", converter = Tile.Converter.class) public Tile tile;

    @Option(names = "--pieces", paramLabel = "DIR") public Path pieces;

    /**
     * Whether this run computes a piece: --tile given, with --pieces; --pieces without --tile is refused
     * ({@code piece} says what a piece is, e.g. "which band of rows to compute").
     */
    public boolean requested(String piece) {
        if (tile == null) {
            if (pieces != null) {
                throw new UserInputException("--pieces DIR goes with --tile I/N (" + piece + ")");
            }
            return false;
        }
        if (pieces == null) {
            throw new UserInputException("--tile " + tile + " needs --pieces DIR, the folder its piece goes to");
        }
        return true;
    }

    /**
     * Refuses more pieces than the result has items ({@code whole} says so, e.g. "a map of --size 16 has only 16
     * rows"), and a --pieces folder that cannot be written.
     */
    public void requireSplittable(int items, String whole) {
        if (tile.count() > items) {
            throw new UserInputException("--tile " + tile + ": " + whole + " to split");
        }
        OutputPaths.requireWritableFolder(pieces, "--pieces");
    }

    /** What submit refuses: it chooses --tile and --pieces itself for the {@code command} it splits. */
    public void refuseForSubmit(String command) {
        if (tile != null || pieces != null) {
            throw new UserInputException("submit chooses --tile and --pieces itself: drop them from the " + command
                    + " options");
        }
    }

    /** The options a command was given, less --tile and --pieces: what merge parses to write the result. */
    public static List<String> argumentsWithoutTile(CommandSpec spec) {
        List<String> given = spec.commandLine().getParseResult().originalArgs();
        int from = given.indexOf(spec.name()) + 1;
        List<String> kept = new ArrayList<>();
        for (int a = from; a < given.size(); a++) {
            String arg = given.get(a);
            if (arg.equals("--tile") || arg.equals("--pieces")) {
                a++; // and its value
            } else if (!arg.startsWith("--tile=") && !arg.startsWith("--pieces=")) {
                kept.add(arg);
            }
        }
        return kept;
    }

    /** Piece {@code index} of {@code count}. */
    public record Tile(int index, int count) {
        /** The file names of this piece: {@code piece-I-of-N} and an extension. */
        public String fileName(String extension) {
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
