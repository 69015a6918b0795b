package diffract.app.jobs;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

/**
 * A command whose result splits into pieces ({@code --tile I/N --pieces DIR}) that {@code merge} assembles: brdfmap
 * (bands of a map's rows) and render with --turntable (runs of frames). {@code submit} runs any of them in pieces, on
 * this machine or as a Slurm job array, through this interface alone.
 */
public interface SplitCommand {
    /** Its --tile and --pieces, which submit chooses itself. */
    TileOptions tiles();

    /**
     * Checks the command as one run would (its outputs included) and that it splits into {@code pieceCount} pieces;
     * refuses, in one line, what it cannot split.
     */
    void validateSplit(int pieceCount);

    /** What the result is made of and the files merge writes; asked once the split is valid. */
    Result result();

    /**
     * The order in which local workers take the {@code pieceCount} pieces (each index once): where some pieces are
     * known to cost more, those first, so that the cheap ones even out the workers' ends (longest processing time
     * first). By default in index order.
     */
    default int[] dispatchOrder(int pieceCount) {
        return java.util.stream.IntStream.range(0, pieceCount).toArray();
    }

    /**
     * A split command's result.
     *
     * @param items     how many items it has: a map's rows, a turntable's frames, a sweep's configurations
     * @param itemsName what the items are, in words
     * @param outputs   each output option merge is given, with its file, in the command's order; the first is the
     *                  one the closing line names
     * @param quiet     whether the command was told to be quiet
     */
    record Result(int items, String itemsName, Map<String, Path> outputs, boolean quiet) {
        public Result {
            if (outputs.isEmpty()) {
                throw new IllegalArgumentException("a split command writes at least one file");
            }
            outputs = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(outputs));
        }

        /** A result written to one file, {@code -o}. */
        public static Result to(Path output, int items, String itemsName, boolean quiet) {
            return new Result(items, itemsName, Map.of("-o", output), quiet);
        }

        /** The output options for merge, each path spelled by {@code path}. */
        public List<String> mergeOutputs(Function<Path, String> path) {
            List<String> options = new ArrayList<>();
            outputs.forEach((option, file) -> options.addAll(List.of(option, path.apply(file))));
            return options;
        }

        /** What the command names first as its output. */
        public Path output() {
            return outputs.values().iterator().next();
        }
    }
}
