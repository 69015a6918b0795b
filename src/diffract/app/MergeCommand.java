package diffract.app;

import diffract.util.Reporter;
import diffract.util.UserInputException;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

/**
 * {@code diffract merge DIR -o MAP.png}: the pieces that {@code brdfmap --tile I/N --pieces DIR} left, checked and
 * assembled into the map, written exactly as one {@code brdfmap} run with their options writes it (the exposure, auto
 * included, is chosen on the whole map here).
 */
@Command(name = "merge", mixinStandardHelpOptions = true, abbreviateSynopsis = true,
        description = "Assemble the pieces of a BRDF map (brdfmap --tile I/N --pieces DIR) into the map: the same "
                + "PNG, PFM and OpenEXR files, bit for bit, as one brdfmap run with the pieces' options writes. "
                + "Pieces missing, there twice, damaged or of another map are refused, named.")
final class MergeCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "DIR", description = "The folder of pieces.")
    Path pieces;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "MAP.png|MAP.exr",
            description = "The map to write, as brdfmap's -o: a PNG at the pieces' --exposure, or OpenEXR.")
    Path output;

    @Option(names = "--pfm", paramLabel = "MAP.pfm", description = "Also write the floats, as brdfmap's --pfm.")
    Path pfm;

    @Option(names = "--exr", paramLabel = "MAP.exr", description = "Also write the floats as OpenEXR, as brdfmap's --exr.")
    Path exr;

    @Mixin
    QuietOption quiet;

    @Override
    public Integer call() throws IOException {
        long start = System.nanoTime();
        Reporter reporter = quiet.reporter();
        PieceFolder.Assembled assembled = PieceFolder.read(pieces);
        PieceManifest m = assembled.manifest();
        BrdfMapCommand single = singleRun(m);
        single.output = output;
        single.picture.pfm = pfm;
        single.picture.exr = exr;
        single.writeMerged(assembled.map(), Double.parseDouble(m.settings().get("phiIDeg")), m.patchWidthUm(),
                m.patchHeightUm(), reporter);
        System.out.printf(Locale.ROOT, "merged %d pieces into %s (%dx%d) in %.1f s%n", m.pieces(), output, m.sizePx(),
                m.sizePx(), (System.nanoTime() - start) * 1e-9);
        return 0;
    }

    /** The brdfmap run the pieces were cut from, read back from their options (its outputs are merge's). */
    private static BrdfMapCommand singleRun(PieceManifest m) {
        List<String> args = new ArrayList<>();
        args.add("brdfmap");
        args.addAll(m.arguments());
        CommandLine.ParseResult parsed;
        try {
            parsed = new CommandLine(new Main()).setCaseInsensitiveEnumValuesAllowed(true)
                    .parseArgs(args.toArray(String[]::new));
        } catch (CommandLine.ParameterException e) {
            throw new UserInputException("merge: the pieces' options no longer parse (" + e.getMessage()
                    + "): compute them again with this diffract");
        }
        BrdfMapCommand single = (BrdfMapCommand) parsed.subcommand().commandSpec().userObject();
        String settings = single.brdf.apply(BrdfMapCommand.base(single.requested())).toString();
        if (!settings.equals(m.settings().get("brdf"))) {
            throw new UserInputException("merge: the pieces' options give other settings in this diffract than in "
                    + "the one that computed them: compute them again with this diffract");
        }
        return single;
    }
}
