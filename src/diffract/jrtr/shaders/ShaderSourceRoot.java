package diffract.jrtr.shaders;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;

/**
 * Where GLSL files come from: the classpath folder {@code /shaders} (inside the jar) or a directory on disk
 * (for editing shaders without rebuilding). Paths are relative, '/'-separated, e.g. {@code engine/unlit.vert}.
 */
public interface ShaderSourceRoot {
    /** The text of {@code path}; throws {@link ShaderException} if there is no such file. */
    String read(String path);

    /** Where files are looked up, for messages. */
    String describe();

    /** Files under the classpath folder {@code /shaders/}. */
    static ShaderSourceRoot classpath() {
        return new ShaderSourceRoot() {
            @Override
            public String read(String path) {
                String resource = "/shaders/" + normalize(path);
                try (InputStream in = ShaderSourceRoot.class.getResourceAsStream(resource)) {
                    if (in == null) {
                        throw new ShaderException("shader file not found: classpath:" + resource);
                    }
                    return new String(in.readAllBytes(), StandardCharsets.UTF_8);
                } catch (IOException e) {
                    throw new ShaderException("cannot read classpath:" + resource + ": " + e.getMessage());
                }
            }

            @Override
            public String describe() {
                return "classpath:/shaders";
            }
        };
    }

    /** Files under {@code directory}. */
    static ShaderSourceRoot directory(Path directory) {
        Path root = directory.toAbsolutePath().normalize();
        return new ShaderSourceRoot() {
            @Override
            public String read(String path) {
                Path file = root.resolve(normalize(path));
                if (!Files.isRegularFile(file)) {
                    throw new ShaderException("shader file not found: " + file);
                }
                try {
                    return Files.readString(file, StandardCharsets.UTF_8);
                } catch (IOException e) {
                    throw new ShaderException("cannot read " + file + ": " + e.getMessage());
                }
            }

            @Override
            public String describe() {
                return root.toString();
            }
        };
    }

    /**
     * Resolves "." and ".." in a '/'-separated relative path; rejects paths that leave the root, so an include
     * cannot read arbitrary files.
     */
    static String normalize(String path) {
        Deque<String> parts = new ArrayDeque<>();
        for (String part : path.replace('\\', '/').split("/")) {
            if (part.isEmpty() || part.equals(".")) {
                continue;
            }
            if (part.equals("..")) {
                if (parts.isEmpty()) {
                    throw new ShaderException("shader path leaves the shader root: " + path);
                }
                parts.removeLast();
            } else {
                parts.addLast(part);
            }
        }
        if (parts.isEmpty()) {
            throw new ShaderException("empty shader path: '" + path + "'");
        }
        return String.join("/", parts);
    }
}
