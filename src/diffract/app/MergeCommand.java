package diffract.app;

import diffract.app.jobs.PieceFolder;
import diffract.app.jobs.PieceManifest;
import diffract.app.options.QuietOption;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

/**
 * {@code diffract merge DIR -o OUT}: the pieces that {@code brdfmap --tile I/N --pieces DIR}, {@code render
 * --turntable F --tile I/N --pieces DIR} or {@code bench --tile I/N --pieces DIR} left, checked and assembled, written
 * exactly as one run of that command with their options writes its result (a map's exposure, auto included, is chosen
 * on the whole map here; a GIF's palette on all its frames; a sweep's Pareto front on all its rows).
 */
@Command(name = "merge", mixinStandardHelpOptions = true, abbreviateSynopsis = true)
final class MergeCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "DIR", descriptionKey = "pieces-folder") Path pieces;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT") Path output;

    @Option(names = "--pfm", paramLabel = "MAP.pfm") Path pfm;

    @Option(names = "--exr", paramLabel = "MAP.exr") Path exr;

    @Mixin QuietOption quiet;

    @Override
    public Integer call() throws IOException {
        long start = System.nanoTime();
        Reporter reporter = quiet.reporter();
        PieceFolder.Assembled assembled = PieceFolder.read(pieces);
        PieceManifest m = assembled.manifest();
        if ("render".equals(m.command())) {
            if (pfm != null || exr != null) {
                throw new UserInputException("merge: the pieces are a turntable's frames: --pfm and --exr go with a "
                        + "BRDF map's pieces; write -o OUT.gif or OUT.png");
            }
            if (!diffract.util.Version.VERSION.equals(m.settings().get("version"))) {
                throw new UserInputException("merge: the pieces were rendered by diffract " + m.settings().get("version")
                        + ", this is " + diffract.util.Version.VERSION + ": compute them again with this diffract");
            }
            RenderCommand single = (RenderCommand) singleRun(m);
            single.output = output;
            single.writeMergedTurntable(assembled.floats(), reporter);
            System.out.printf(Locale.ROOT, "merged %d pieces into %s (%d frames) in %.1f s%n", m.pieces(), output,
                    m.items(), (System.nanoTime() - start) * 1e-9);
            return 0;
        }
        if ("bench".equals(m.command())) {
            if (pfm != null || exr != null) {
                throw new UserInputException("merge: the pieces are a bench sweep's rows: --pfm and --exr go with a "
                        + "BRDF map's pieces; write -o DIR, the bench's folder");
            }
            if (!diffract.util.Version.VERSION.equals(m.settings().get("version"))) {
                throw new UserInputException("merge: the pieces were measured by diffract "
                        + m.settings().get("version") + ", this is " + diffract.util.Version.VERSION
                        + ": measure them again with this diffract");
            }
            BenchCommand single = (BenchCommand) singleRun(m);
            single.outputDir = output;
            single.writeMerged(assembled.pieces(), reporter);
            System.out.printf(Locale.ROOT, "merged %d pieces into %s (%d configurations) in %.1f s%n", m.pieces(),
                    output, m.items(), (System.nanoTime() - start) * 1e-9);
            return 0;
        }
        BrdfMapCommand single = (BrdfMapCommand) singleRun(m);
        String settings = single.brdf.apply(BrdfMapCommand.base(single.requested())).toString();
        if (!settings.equals(m.settings().get("brdf"))) {
            throw new UserInputException("merge: the pieces' options give other settings in this diffract than in "
                    + "the one that computed them: compute them again with this diffract");
        }
        single.output = output;
        single.picture.pfm = pfm;
        single.picture.exr = exr;
        single.writeMerged(assembled.floats(), m.number("phiIDeg"), m.number("patchWidthUm"), m.number("patchHeightUm"),
                reporter);
        System.out.printf(Locale.ROOT, "merged %d pieces into %s (%dx%d) in %.1f s%n", m.pieces(), output, m.items(),
                m.items(), (System.nanoTime() - start) * 1e-9);
        return 0;
    }

    /** The run the pieces were cut from, read back from their command and options (its outputs are merge's). */
    private static Object singleRun(PieceManifest m) {
        List<String> args = new ArrayList<>();
        args.add(m.command());
        args.addAll(m.arguments());
        CommandLine.ParseResult parsed;
        try {
            parsed = Main.commandLine(String.valueOf(m.command()))
                    .parseArgs(args.toArray(String[]::new));
        } catch (CommandLine.ParameterException e) {
            throw new UserInputException("merge: the pieces' options no longer parse (" + e.getMessage()
                    + "): compute them again with this diffract");
        }
        return parsed.subcommand().commandSpec().userObject();
    }
}