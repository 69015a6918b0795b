package diffract.app;

import diffract.app.options.CacheOption;
import diffract.app.options.GpuOption;
import diffract.app.options.OptionTypes;
import diffract.app.options.QuietOption;
import diffract.jrtr.contexts.HeadlessGL;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import diffract.util.ImageFiles;
import diffract.util.OutputPaths;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/**
 * {@code diffract demo}, the main job: with a screen, the interactive viewer on the default scene, a coiled corn snake
 * whose scales carry the Elaphe-like snake-skin patch; without one, the same view rendered offscreen (headless EGL,
 * no X server needed) to {@code out/demo.png}; without any OpenGL, the CPU reference BRDF map of a blazed grating.
 * It prints the path of every picture it writes.
 */
@Command(name = "demo", mixinStandardHelpOptions = true)
final class DemoCommand implements Callable<Integer> {
    @Mixin GpuOption gpu;
    @Mixin QuietOption quiet;
    @Mixin CacheOption cache;

    @Option(names = {"-o", "--output-dir"}, defaultValue = "out", paramLabel = "DIR") Path outputDir;

    @Option(names = "--size", defaultValue = "640x400", paramLabel = "WxH",
            converter = OptionTypes.ImageSize.Converter.class)
    OptionTypes.ImageSize size;

    /** The arguments of a command the demo runs, with the demo's {@code --quiet} and {@code --no-cache}. */
    private String[] withDemoOptions(String... args) {
        List<String> out = new ArrayList<>(List.of(args));
        if (quiet.quiet) {
            out.add("--quiet");
        }
        out.addAll(cache.arguments());
        return out.toArray(new String[0]);
    }

    /**
     * The view: the default scene {@code assets/scenes/snake-elaphe.json}, a coiled corn snake with scales, its
     * pigment, a clear sky as 8 extended lights, a ground with the key light's shadow (docs/guide/staging.md). A 10 um
     * coherence length (sigma_s = 2.5 um, a less coherent source than sunlight's 65 um) widens the orders of the 9 um
     * periodic patch into bands that a 640 x 400 picture resolves (with 65 um they are a fraction of a pixel wide).
     */
    static final String DEFAULT_SCENE = ShippedScenes.DEMO;
    /** The offscreen picture of the view, in the output folder. */
    static final String PICTURE = "demo.png";
    /** Without OpenGL: the CPU BRDF map, in the output folder. */
    static final String CPU_MAP = "demo-brdfmap.png";

    /**
     * The default scene as a file: the repository's {@code assets/scenes/} when run from its root, else the copy
     * inside the jar written into {@code outputDir} (the scene names no other files, so it works from there).
     */
    static Path defaultScene(Path outputDir) throws IOException {
        Path inRepository = ShippedScenes.inRepository(DEFAULT_SCENE);
        if (inRepository != null) {
            return inRepository;
        }
        Path copy = outputDir.resolve(DEFAULT_SCENE);
        byte[] scene = ShippedScenes.fromJar(DEFAULT_SCENE);
        ImageFiles.writeAtomically(copy, out -> out.write(scene));
        return copy;
    }

    private String sizeText() {
        return size.width() + "x" + size.height();
    }

    @Override
    public Integer call() throws Exception {
        // the folder, and what the demo may write there: the scene's copy, the picture, or the CPU map instead
        OutputPaths.require(OutputPaths.folder("-o", outputDir),
                OutputPaths.file("-o", outputDir.resolve(DEFAULT_SCENE), DEFAULT_SCENE, ".json"),
                OutputPaths.file("-o", outputDir.resolve(PICTURE), PICTURE, ".png"),
                OutputPaths.file("-o", outputDir.resolve(CPU_MAP), CPU_MAP, ".png"));
        boolean screen = ViewCommand.noDisplayProblem(System.getenv(), System.getProperty("os.name", "")).isEmpty();
        boolean gl = HeadlessGL.problem().isEmpty();
        if (screen) {
            return Main.execute(withDemoOptions("view", defaultScene(outputDir).toString(), "--size", sizeText()));
        }
        if (gl) {
            Path png = outputDir.resolve(PICTURE);
            List<String> render = new ArrayList<>(List.of("render", defaultScene(outputDir).toString(), "--size",
                    sizeText(), "-o", png.toString()));
            render.addAll(gpu.arguments());
            int code = Main.execute(withDemoOptions(render.toArray(new String[0])));
            if (code == 0) {
                System.out.println(png.toAbsolutePath());
            }
            return code;
        }
        System.err.println(HeadlessGL.problem().orElse("no OpenGL") + ": CPU BRDF map instead");
        Path png = outputDir.resolve(CPU_MAP);
        int code = Main.execute(withDemoOptions("brdfmap", "--synthetic", "blazed", "--theta-i", "30", "--variant",
                "reference", "--exposure", "auto", "--size", "256", "-o", png.toString()));
        if (code == 0) {
            System.out.println(png.toAbsolutePath());
        }
        return code;
    }
}
