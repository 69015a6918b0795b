package diffract.app;

import diffract.app.options.OptionTypes;
import diffract.app.options.QuietOption;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.spectra.TaylorBound;
import diffract.optics.spectra.TaylorTerms;
import diffract.precompute.TermFolders;
import diffract.precompute.TermSidecar;
import diffract.precompute.TermStore;
import diffract.precompute.ThesisFormat;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.util.Version;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code diffract convert-terms}: precomputed terms from one on-disk format into the other, without any FFT. */
@Command(name = "convert-terms", mixinStandardHelpOptions = true)
final class ConvertTermsCommand implements Callable<Integer> {
    @Option(names = "--from", required = true, paramLabel = "DIR") Path from;

    @Option(names = "--to", required = true, paramLabel = "DIR") Path to;

    @Option(names = "--format", paramLabel = "F") TermFolders.Format format;

    @Option(names = "--terms-height-unit", defaultValue = "auto", paramLabel = "UNIT",
            converter = OptionTypes.HeightUnitConverter.class)
    ThesisFormat.HeightUnit unit;

    @Mixin QuietOption quiet;

    @Override
    public Integer call() throws IOException {
        OutputPaths.requireWritableFolder(to, "--to");
        Reporter reporter = quiet.reporter();
        TermFolders.Format source = TermFolders.detect(from);
        TermFolders.Format target = format != null ? format
                : source == TermFolders.Format.NATIVE ? TermFolders.Format.THESIS : TermFolders.Format.NATIVE;
        if (Files.exists(to) && Files.isSameFile(from, to)) {
            throw new UserInputException("--to must differ from --from (" + to + ")");
        }
        long start = System.nanoTime();
        TaylorTerms terms = TermFolders.read(from, unit, reporter);
        TermSidecar sidecar = source == TermFolders.Format.NATIVE ? TermStore.readSidecar(from) : null;
        if (target == TermFolders.Format.THESIS) {
            ThesisFormat.Provenance provenance = sidecar != null
                    ? new ThesisFormat.Provenance(sidecar.patch().source(), sidecar.patch().sha256(),
                    sidecar.patch().maxHeightUm())
                    : new ThesisFormat.Provenance("converted from " + from, null, null);
            ThesisFormat.write(to, terms, provenance, reporter);
        } else {
            TermSidecar.Patch patch = sidecar != null ? sidecar.patch()
                    : new TermSidecar.Patch("converted from " + from + " (thesis format)", null, terms.rows(),
                    terms.cols(), terms.pixelSizeXUm(), terms.pixelSizeYUm(), null, terms.maxAbsHeightUm());
            TermSidecar.Selection selection = sidecar != null ? sidecar.selection() : convertedSelection(terms);
            TermStore.write(to, terms, patch, selection, Version.VERSION);
        }
        System.out.printf(Locale.ROOT, "converted %d terms of %dx%d from %s (%s) to %s (%s) in %.2f s%n",
                terms.termCount(), terms.rows(), terms.cols(), from, name(source), to, name(target),
                (System.nanoTime() - start) * 1e-9);
        return 0;
    }

    /** A thesis folder does not say how N was chosen: record "converted" and the bound N gives at 380 nm. */
    private static TermSidecar.Selection convertedSelection(TaylorTerms terms) {
        double lambdaMinNm = SpectralSettings.LAMBDA_MIN_NM;
        double x = TaylorBound.maxPhase(lambdaMinNm, terms.maxAbsHeightUm());
        return new TermSidecar.Selection("converted", null, lambdaMinNm, x,
                TaylorBound.lagrangeRemainder(x, terms.highestOrder()));
    }

    private static String name(TermFolders.Format f) {
        return f.name().toLowerCase(Locale.ROOT);
    }
}
