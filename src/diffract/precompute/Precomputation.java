package diffract.precompute;

import diffract.optics.HeightField;
import diffract.optics.InvalidSettingException;
import diffract.optics.Quantity;
import diffract.optics.TaylorBound;
import diffract.optics.TaylorExpansion;
import diffract.optics.TaylorSettings;
import diffract.optics.TaylorTerms;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.util.Version;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Precomputes Taylor terms once per (patch content, N): into a folder the user names, or into the user cache
 * ({@code $DIFFRACT_CACHE}, else {@code $XDG_CACHE_HOME/diffract}, else {@code ~/.cache/diffract}). A folder whose
 * sidecar has the same patch hash and N is reused without any FFT.
 */
public final class Precomputation {
    private Precomputation() {
    }

    /**
     * What to precompute. Exactly one of {@code highestOrder} and {@code tolerance} is set.
     *
     * @param meanSubtracted the patch (mean removed)
     * @param source         where it came from, for the sidecar
     * @param maxHeightUm    the user's --max-height, or null
     * @param highestOrder   N given by the user (n = 0..N)
     * @param tolerance      EPS for the Lagrange bound (001 sec. 3.3.3)
     * @param lambdaMinNm    the shortest wavelength rendered (enters the bound)
     */
    public record Request(HeightField meanSubtracted, String source, Double maxHeightUm, Integer highestOrder,
                          Double tolerance, double lambdaMinNm) {
        public Request {
            if ((highestOrder == null) == (tolerance == null)) {
                throw new IllegalArgumentException("give either N or a tolerance (not both, not neither)");
            }
            if (highestOrder != null) {
                new TaylorSettings(highestOrder, 0, TaylorExpansion.AUTO); // N's one range
            }
            if (tolerance != null && !(tolerance > 0 && tolerance < 1)) {
                throw new InvalidSettingException(Quantity.ORDER_TOLERANCE, Quantity.ORDER_TOLERANCE.words()
                        + " must be in (0, 1), got " + tolerance);
            }
            if (!(lambdaMinNm > 0)) {
                throw new InvalidSettingException(Quantity.LAMBDA_MIN, Quantity.LAMBDA_MIN.words()
                        + " must be > 0 nm, got " + lambdaMinNm);
            }
        }
    }

    /** @param terms null when the caller did not ask to load them and they were reused */
    public record Result(TaylorTerms terms, TermSidecar sidecar, Path dir, boolean reused) {
    }

    /** The highest order N and how it was chosen; prints the choice and its bound. */
    public static TermSidecar.Selection select(Request request, Reporter reporter) {
        double x = TaylorBound.maxPhase(request.lambdaMinNm(), request.meanSubtracted().maxAbsHeightUm());
        int n;
        String mode;
        if (request.tolerance() != null) {
            n = TaylorBound.termsForTolerance(x, request.tolerance());
            mode = "tolerance";
            if (n > TaylorSettings.MAX_HIGHEST_ORDER) {
                throw new InvalidSettingException(Quantity.ORDER_TOLERANCE, String.format(Locale.ROOT,
                        "the tolerance %s needs N = %d for this patch (x = %.1f), above the limit %d: use a larger "
                                + "tolerance; the phase-centred expansion needs no large N", request.tolerance(), n,
                        x, TaylorSettings.MAX_HIGHEST_ORDER));
            }
        } else {
            n = request.highestOrder();
            mode = "terms";
        }
        double bound = TaylorBound.lagrangeRemainder(x, n);
        reporter.info(String.format("Taylor order N = %d (terms n = 0..%d): x = 2 pi / %.0f nm * 2 * max|h| %.4f um = %.4f,"
                        + " remainder bound x^(N+1) e^x / (N+1)! = %.3g%s", n, n, request.lambdaMinNm(),
                request.meanSubtracted().maxAbsHeightUm(), x, bound,
                request.tolerance() != null ? " <= " + request.tolerance() : ""));
        return new TermSidecar.Selection(mode, request.tolerance(), request.lambdaMinNm(), x, bound);
    }

    /** Precomputes into {@code dir} unless it already holds the same terms. */
    public static Result intoFolder(Request request, Path dir, boolean loadTerms, Reporter reporter) {
        TermSidecar.Selection selection = select(request, reporter);
        int n = highestOrderOf(request, selection);
        HeightField field = request.meanSubtracted();
        String sha = field.contentSha256();
        TermSidecar existing = TermStore.readSidecar(dir);
        if (existing != null && sha.equals(existing.patch().sha256()) && existing.highestOrder() == n
                && TermStore.dataLooksComplete(dir, existing)) {
            if (!loadTerms) {
                return new Result(null, existing, dir, true);
            }
            try {
                return new Result(TermStore.read(dir), existing, dir, true);
            } catch (UserInputException e) {
                reporter.warn(e.getMessage() + " - recomputing");
            }
        }
        TaylorTerms terms = TaylorTermComputer.compute(field, n, reporter);
        TermSidecar.Patch patch = new TermSidecar.Patch(request.source(), sha, field.rows(), field.cols(),
                field.pixelSizeXUm(), field.pixelSizeYUm(), request.maxHeightUm(), field.maxAbsHeightUm());
        try {
            TermSidecar sidecar = TermStore.write(dir, terms, patch, selection, Version.VERSION);
            return new Result(terms, sidecar, dir, false);
        } catch (IOException e) {
            throw new UserInputException("cannot write precomputed terms to " + dir + ": " + e.getMessage(), e);
        }
    }

    /** What {@link #intoThesisFolder} did. */
    public record ThesisResult(int termCount, Path dir, boolean reused) {
    }

    /**
     * Precomputes into {@code dir} in the thesis' Octave layout ({@link ThesisFormat}) unless it already holds
     * the same terms: a diffract.json with the same patch hash and N, and all term files of the right size.
     */
    public static ThesisResult intoThesisFolder(Request request, Path dir, Reporter reporter) {
        TermSidecar.Selection selection = select(request, reporter);
        int n = highestOrderOf(request, selection);
        HeightField field = request.meanSubtracted();
        String sha = field.contentSha256();
        ThesisExtras existing = java.nio.file.Files.isDirectory(dir) ? ThesisReader.readExtras(dir) : null;
        if (existing != null && sha.equals(existing.patchSha256()) && existing.highestOrder() == n
                && ThesisReader.filesLookComplete(dir, existing)) {
            return new ThesisResult(n + 1, dir, true);
        }
        TaylorTerms terms = TaylorTermComputer.compute(field, n, reporter);
        try {
            ThesisFormat.write(dir, terms, new ThesisFormat.Provenance(request.source(), sha, request.maxHeightUm()),
                    reporter);
        } catch (IOException e) {
            throw new UserInputException("cannot write thesis-format terms to " + dir + ": " + e.getMessage(), e);
        }
        return new ThesisResult(n + 1, dir, false);
    }

    /** Terms from the user cache, computed on first use. */
    public static TaylorTerms cached(Request request, Reporter reporter) {
        TermSidecar.Selection selection = select(request, Reporter.SILENT);
        int n = highestOrderOf(request, selection);
        String sha = request.meanSubtracted().contentSha256();
        Path dir = cacheRoot().resolve("terms").resolve(sha.substring(0, 24) + "-n" + n);
        Result result = intoFolder(request, dir, true, reporter);
        if (!result.reused()) {
            reporter.info("cached Taylor terms in " + dir);
        }
        return result.terms();
    }

    public static Path cacheRoot() {
        String explicit = System.getenv("DIFFRACT_CACHE");
        if (explicit != null && !explicit.isBlank()) {
            return Path.of(explicit);
        }
        String xdg = System.getenv("XDG_CACHE_HOME");
        if (xdg != null && !xdg.isBlank()) {
            return Path.of(xdg, "diffract");
        }
        return Path.of(System.getProperty("user.home"), ".cache", "diffract");
    }

    private static int highestOrderOf(Request request, TermSidecar.Selection selection) {
        if (request.highestOrder() != null) {
            return request.highestOrder();
        }
        double x = selection.maxPhase();
        return TaylorBound.termsForTolerance(x, request.tolerance());
    }

}
