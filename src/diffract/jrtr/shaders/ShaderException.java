package diffract.jrtr.shaders;

import java.util.List;

/**
 * A shader could not be loaded, compiled or linked. For compile errors the message lists one diagnostic per
 * line in the form {@code original-file.glsl:LINE: message}, naming the file and line the author wrote (not the
 * line in the preprocessed text the driver saw).
 */
public class ShaderException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final List<String> diagnostics;

    public ShaderException(String message) {
        this(message, List.of());
    }

    public ShaderException(String summary, List<String> diagnostics) {
        super(diagnostics.isEmpty() ? summary : summary + "\n" + String.join("\n", diagnostics));
        this.diagnostics = List.copyOf(diagnostics);
    }

    /** The translated driver messages, {@code file:LINE: message} where a line was given. */
    public List<String> diagnostics() {
        return diagnostics;
    }
}
