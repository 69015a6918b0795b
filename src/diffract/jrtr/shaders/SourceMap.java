package diffract.jrtr.shaders;

import java.util.ArrayList;
import java.util.List;

/**
 * For each line of a preprocessed shader (the text the driver compiles), the file and line it came from.
 * Used instead of {@code #line} directives because GLSL's {@code #line} takes only a source-string NUMBER, and
 * GLSL versions disagree on whether it names the next line or the one after.
 */
public final class SourceMap {
    /** An original position: file path relative to the shader root, 1-based line. */
    public record Location(String file, int line) {
        @Override
        public String toString() {
            return file + ":" + line;
        }
    }

    private final List<Location> lines = new ArrayList<>();

    void add(String file, int line) {
        lines.add(new Location(file, line));
    }

    /** Number of lines in the preprocessed text. */
    public int lineCount() {
        return lines.size();
    }

    /**
     * Where 1-based line {@code generatedLine} of the preprocessed text came from. Lines past the end (drivers
     * report "unexpected end of file" one past the last line) map to the last line.
     */
    public Location locate(int generatedLine) {
        if (lines.isEmpty()) {
            throw new IllegalStateException("empty source map");
        }
        int index = Math.max(1, Math.min(generatedLine, lines.size())) - 1;
        return lines.get(index);
    }
}
