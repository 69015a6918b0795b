package diffract.app;

import diffract.scene.Scene;
import diffract.scene.SceneFile;
import diffract.util.UserInputException;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The scene files shipped in {@code assets/scenes/}: the repository's when a command runs from its root, else the
 * copies inside the jar. They name no other files, so they read the same from either place.
 */
final class ShippedScenes {
    /** The demo: a coiled corn snake under a clear sky, on a ground ({@link DemoCommand}). */
    static final String DEMO = "snake-elaphe.json";
    /** What {@code --shape snake} shows: the demo's snake, lit by its key light alone. */
    static final String VIEWER_SNAKE = "viewer-snake.json";

    private ShippedScenes() {
    }

    /** Where the scene is in the repository, as a path relative to it. */
    static Path relative(String name) {
        return Path.of("assets", "scenes", name);
    }

    /** The file in the repository, when the command runs from its root; else null. */
    static Path inRepository(String name) {
        Path file = relative(name);
        return Files.isRegularFile(file) ? file : null;
    }

    /** The scene's text as the jar holds it. */
    static byte[] fromJar(String name) throws IOException {
        try (InputStream in = ShippedScenes.class.getResourceAsStream("/assets/scenes/" + name)) {
            if (in == null) {
                throw new UserInputException("the shipped scene " + name + " is missing from the jar; rebuild it");
            }
            return in.readAllBytes();
        }
    }

    /** The scene, read from the repository or the jar. */
    static Scene load(String name) {
        Path file = inRepository(name);
        if (file != null) {
            return SceneFile.load(file);
        }
        try {
            return SceneFile.parse(new String(fromJar(name), StandardCharsets.UTF_8), relative(name) + " (in the jar)",
                    Path.of("").toAbsolutePath(), relative(name));
        } catch (IOException e) {
            throw new UserInputException("cannot read the shipped scene " + name + " from the jar: " + e.getMessage());
        }
    }
}
