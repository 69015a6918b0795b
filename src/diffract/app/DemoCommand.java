package diffract.app;

import diffract.optics.SyntheticPatches;
import diffract.optics.io.GsfWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

import java.nio.file.Path;
import java.util.concurrent.Callable;

/**
 * {@code diffract demo}: the main job until the interactive viewer exists (issue #4): writes a blazed grating
 * made by code and renders its colour BRDF map with the exact reference, printing where the picture is.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = {"Render the demo: the colour BRDF map of a blazed grating (d = 2.5 um) lit at 30 degrees,",
                "with the exact reference model, into out/demo-brdfmap.png."})
final class DemoCommand implements Callable<Integer> {
    @Option(names = {"-o", "--output-dir"}, defaultValue = "out", paramLabel = "DIR", description = "Default ${DEFAULT-VALUE}.")
    Path outputDir;

    @Option(names = "--size", defaultValue = "256", paramLabel = "S", description = "Map size (default ${DEFAULT-VALUE}).")
    int size;

    @Override
    public Integer call() throws Exception {
        Path patch = outputDir.resolve("demo-blazed-grating.gsf");
        GsfWriter.write(patch, SyntheticPatches.blazed(2.5, 0.2, 25, 26, 16));
        Path png = outputDir.resolve("demo-brdfmap.png");
        int code = Main.execute("brdfmap", "--patch", patch.toString(), "--theta-i", "30", "--variant", "reference",
                "--exposure", "auto", "--size", Integer.toString(size), "-o", png.toString());
        if (code == 0) {
            System.out.println(png.toAbsolutePath());
        }
        return code;
    }
}
