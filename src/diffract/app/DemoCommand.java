package diffract.app;

import diffract.jrtr.DisplayCheck;
import diffract.optics.SyntheticPatches;
import diffract.optics.io.GsfWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

import java.nio.file.Path;
import java.util.concurrent.Callable;

/**
 * {@code diffract demo}, the main job: with a screen, the interactive viewer on the procedural snake covered with the
 * Elaphe-like snake-skin patch; without one (the launcher then runs it under a private Xvfb), the same view rendered
 * offscreen to {@code out/demo.png}; without any OpenGL, the CPU reference BRDF map of a blazed grating. It prints
 * the path of every picture it writes.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = {"The demo: the viewer on the iridescent procedural snake (Elaphe-like skin patch) when there is a",
                "screen; otherwise the same view rendered to out/demo.png (and, without OpenGL, the CPU BRDF map of",
                "a blazed grating to out/demo-brdfmap.png)."})
final class DemoCommand implements Callable<Integer> {
    @Option(names = {"-o", "--output-dir"}, defaultValue = "out", paramLabel = "DIR", description = "Default ${DEFAULT-VALUE}.")
    Path outputDir;

    @Option(names = "--size", defaultValue = "640x400", paramLabel = "WxH", description = "Picture size (default ${DEFAULT-VALUE}).")
    String size;

    /**
     * The view: 20 Taylor terms and 10 nm steps keep llvmpipe near a frame a second; a 10 um coherence length (a
     * less coherent source than sunlight's 65 um) widens the orders of the 9 um periodic patch into bands that a
     * 480 x 360 picture resolves (with 65 um they are a fraction of a pixel wide).
     */
    static final String[] VIEW = {"--synthetic", "elaphe-like", "--shape", "snake", "--no-pigmentation", "--variant",
        "flss", "--terms", "20", "--lambda-step", "10", "--coherence-length", "10", "--theta-i", "60", "--phi-i", "90",
        "--exposure", "50", "--elevation", "30", "--azimuth", "15", "--distance", "1.8"};

    private static String[] concat(String[] options, String command, String... more) {
        String[] all = new String[1 + options.length + more.length];
        all[0] = command;
        System.arraycopy(options, 0, all, 1, options.length);
        System.arraycopy(more, 0, all, 1 + options.length, more.length);
        return all;
    }

    @Override
    public Integer call() throws Exception {
        boolean gl = DisplayCheck.problem().isEmpty();
        boolean screen = gl && !"1".equals(System.getenv(ViewCommand.PRIVATE_XVFB_VARIABLE));
        if (screen) {
            return Main.execute(concat(VIEW, "view", "--size", size));
        }
        if (gl) {
            Path png = outputDir.resolve("demo.png");
            int code = Main.execute(concat(VIEW, "render", "--size", size, "-o", png.toString()));
            if (code == 0) {
                System.out.println(png.toAbsolutePath());
            }
            return code;
        }
        System.err.println("no OpenGL display (install xvfb for the rendered view): CPU BRDF map instead");
        Path patch = outputDir.resolve("demo-blazed-grating.gsf");
        GsfWriter.write(patch, SyntheticPatches.blazed(2.5, 0.2, 25, 26, 16));
        Path png = outputDir.resolve("demo-brdfmap.png");
        int code = Main.execute("brdfmap", "--patch", patch.toString(), "--theta-i", "30", "--variant", "reference",
                "--exposure", "auto", "--size", "256", "-o", png.toString());
        if (code == 0) {
            System.out.println(png.toAbsolutePath());
        }
        return code;
    }
}
