package diffract.app;

import java.nio.file.Path;
import java.util.List;
import java.util.function.Function;

/**
 * A command whose result splits into pieces ({@code --tile I/N --pieces DIR}) that {@code merge} assembles: brdfmap
 * (bands of a map's rows) and render with --turntable (runs of frames). {@code submit} runs any of them in pieces, on
 * this machine or as a Slurm job array, through this interface alone.
 */
interface SplitCommand {
    /** The command's name, as the pieces run it. */
    String name();

    /**
     * Checks the command as one run would (its outputs included) and that it splits into {@code pieceCount} pieces;
     * refuses, in one line, what it cannot split.
     */
    void validateSplit(int pieceCount);

    /** How many items the result has: a map's rows, a turntable's frames. */
    int items();

    /** What the items are, in words: rows, frames. */
    String itemsName();

    /** The output options merge is given to write the command's files ({@code path} spells each path). */
    List<String> mergeOutputs(Function<Path, String> path);

    /** What the command names first as its output, for the closing line. */
    Path output();

    /** Whether the command was told to be quiet. */
    boolean quiet();

    /**
     * The order in which local workers take the {@code pieceCount} pieces (each index once): where some pieces are
     * known to cost more, those first, so that the cheap ones even out the workers' ends (longest processing time
     * first). By default in index order.
     */
    default int[] dispatchOrder(int pieceCount) {
        return java.util.stream.IntStream.range(0, pieceCount).toArray();
    }
}
