package diffract.app;

import diffract.app.options.CacheOption;
import diffract.app.options.QuietOption;
import diffract.jrtr.contexts.DisplayCheck;
import diffract.optics.Methods;
import diffract.scene.Scene;
import diffract.scene.SceneSetup;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.viewer.KeyBindings;
import diffract.viewer.ViewerModel;
import diffract.viewer.frame.RecentFiles;
import diffract.viewer.frame.ViewerFrame;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;

/** {@code diffract view}: the interactive viewer. */
@Command(name = "view", mixinStandardHelpOptions = true, abbreviateSynopsis = true)
final class ViewCommand implements Callable<Integer> {
    /** Set by the launcher when it runs a command under its own private Xvfb, which nobody can see. */
    static final String PRIVATE_XVFB_VARIABLE = "DIFFRACT_PRIVATE_XVFB";
    static final String NO_DISPLAY_MESSAGE =
            "no display: the viewer needs a screen; use ./diffract render [the same options] -o OUT.png";

    @Mixin ViewerOptions options;
    @Mixin QuietOption quiet;
    @Mixin CacheOption cache;

    @Option(names = "--screenshot-dir", defaultValue = "out", paramLabel = "DIR") Path screenshotDir;

    @Spec CommandSpec spec;

    @Option(names = "--screenshot-when-refined", hidden = true) boolean screenshotWhenRefined;

    /** The window's size unless --size or the scene says otherwise. */
    private static final Scene.ImageSize WINDOW = new Scene.ImageSize(800, 600);

    @Override
    public Integer call() throws Exception {
        defaults(options);
        options.validate();
        if (options.dumpedScene(WINDOW)) {
            return 0;
        }
        if (spec.commandLine().getParseResult().hasMatchedOption("--screenshot-dir")) {
            // the default folder is made when the first screenshot is saved; a folder named is checked now
            OutputPaths.requireWritableFolder(screenshotDir, "--screenshot-dir");
        }
        Optional<String> problem = noDisplayProblem(System.getenv(), System.getProperty("os.name", ""));
        if (problem.isPresent()) {
            throw new UserInputException(problem.get());
        }
        Reporter reporter = quiet.reporter();
        Scene.ImageSize window = options.imageSize(WINDOW);
        SceneSetup setup = options.setup(window, reporter);
        Scene scene = options.scene(window);
        if (setup.exposure() != scene.material().exposure()) {
            scene = scene.withMaterial(scene.material().withExposure(setup.exposure())); // --exposure auto's choice
        }
        ViewerModel model = ViewerModel.load(setup, reporter);
        System.out.print(KeyBindings.helpText());
        // the frame opens at once: the view shows a preview while it refines, and bakes a baked table in the background
        try (ViewerFrame frame = new ViewerFrame(scene, model, window.width(), window.height(), screenshotDir,
                options::withShape, RecentFiles.user(), reporter)) {
            reportFirstPicture(frame, reporter);
            if (screenshotWhenRefined) {
                while (!frame.view().refinement().isRefined(frame.view().model().state())
                        && !frame.isCloseRequested()) {
                    Thread.sleep(50);
                }
                frame.view().controller().screenshot().get();
                // the inset and the panels once their map is drawn, then the whole frame as the screen shows it
                long until = System.nanoTime() + 120_000_000_000L;
                while (!frame.inset().showsCurrent() && System.nanoTime() < until) {
                    Thread.sleep(50);
                }
                Thread.sleep(2 * diffract.viewer.frame.ViewerFrame.refreshMs());
                System.out.println("frame: " + frame.saveFrameScreenshot());
                return 0;
            }
            frame.awaitCloseRequest();
        }
        return 0;
    }

    /**
     * Says, once, how long after the start of the process the view first showed a picture (a preview's pass, or the
     * refined one): a daemon thread watches the refinement.
     */
    private static void reportFirstPicture(ViewerFrame frame, Reporter reporter) {
        long startMillis = java.lang.management.ManagementFactory.getRuntimeMXBean().getStartTime();
        Thread watcher = new Thread(() -> {
            try {
                while (frame.view() == null || frame.view().refinement().passesCompleted() == 0) {
                    Thread.sleep(20);
                }
                reporter.info(String.format(java.util.Locale.ROOT, "first picture %.1f s after the start",
                        (System.currentTimeMillis() - startMillis) / 1000.0));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "diffract-viewer-first-picture");
        watcher.setDaemon(true);
        watcher.start();
    }

    /**
     * What {@code view} shows when the options do not say: the baked table of the lobes method (one lookup per pixel,
     * baked behind the preview), and a shape without a scene under the first look's soft light
     * ({@link ViewerOptions#firstLook}).
     */
    static void defaults(ViewerOptions options) {
        options.defaultVariant(Methods.Role.TABLE.method());
        options.firstLook();
    }

    /**
     * Why the viewer cannot open a window here: no X display at all, or only the launcher's private Xvfb (an
     * invisible screen: a window there helps nobody, a picture from {@code render} does).
     */
    static Optional<String> noDisplayProblem(Map<String, String> environment, String osName) {
        if ("1".equals(environment.get(PRIVATE_XVFB_VARIABLE))
                || DisplayCheck.problem(environment, osName).isPresent()) {
            return Optional.of(NO_DISPLAY_MESSAGE);
        }
        return Optional.empty();
    }
}
