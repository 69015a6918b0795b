package diffract.precompute;

import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.TaylorBound;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.spectra.TaylorSettings;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.DiskCache;
import diffract.util.FolderLock;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.util.Version;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Precomputes Taylor terms once per (patch content, N): into a folder the user names, or into the user's disk cache
 * ({@link DiskCache}, where they are folder entries of kind {@value #CACHE_KIND}). A folder whose sidecar has the
 * same patch hash and N, and whose data pass their checksum, is reused without any FFT; a damaged one is recomputed.
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

    /**
     * Precomputes into {@code dir} unless it already holds the same terms, verified. A folder whose sidecar is
     * unreadable or whose data fail their checksum is recomputed with a one-line warning; temporary files a killed
     * writer left are removed. Writers hold the folder's {@link FolderLock}, so concurrent precomputes into one
     * folder end in one consistent result (the later one reuses what the first wrote).
     */
    public static Result intoFolder(Request request, Path dir, boolean loadTerms, Reporter reporter) {
        return intoFolder(request, dir, loadTerms, false, reporter);
    }

    private static Result intoFolder(Request request, Path dir, boolean loadTerms, boolean inMemoryIfUnwritable,
                                     Reporter reporter) {
        TermSidecar.Selection selection = select(request, reporter);
        int n = highestOrderOf(request, selection);
        String sha = request.meanSubtracted().contentSha256();
        Result reused = reuse(dir, sha, n, loadTerms, null); // without the lock: a writer may be busy, say nothing
        if (reused != null) {
            return reused;
        }
        FolderLock lock;
        try {
            lock = FolderLock.acquire(dir, reporter);
        } catch (IOException e) {
            if (!inMemoryIfUnwritable) {
                throw new UserInputException("cannot write precomputed terms to " + dir + ": " + reason(e)
                        + "; choose another folder", e);
            }
            reporter.info("the term cache " + dir + " is not writable (" + reason(e)
                    + "): computing the terms in memory, not caching them");
            return new Result(compute(request, n, reporter), null, dir, false);
        }
        try (lock) {
            reused = reuse(dir, sha, n, loadTerms, reporter);
            if (reused != null) {
                return reused;
            }
            int stale = lock.removeStaleTemporaries();
            if (stale > 0) {
                reporter.info("removed " + stale + " temporary file" + (stale == 1 ? "" : "s")
                        + " an interrupted write left in " + dir);
            }
            TaylorTerms terms = compute(request, n, reporter);
            HeightField field = request.meanSubtracted();
            TermSidecar.Patch patch = new TermSidecar.Patch(request.source(), sha, field.rows(), field.cols(),
                    field.pixelSizeXUm(), field.pixelSizeYUm(), request.maxHeightUm(), field.maxAbsHeightUm());
            try {
                TermSidecar sidecar = TermStore.write(dir, terms, patch, selection, Version.VERSION);
                return new Result(terms, sidecar, dir, false);
            } catch (IOException e) {
                if (!inMemoryIfUnwritable) {
                    throw new UserInputException("cannot write precomputed terms to " + dir + ": " + reason(e), e);
                }
                reporter.warn("cannot write the term cache " + dir + " (" + reason(e)
                        + "): the terms are used from memory, not cached");
                return new Result(terms, null, dir, false);
            }
        } catch (IOException e) { // closing the lock or listing the folder
            throw new UserInputException("cannot use " + dir + ": " + reason(e), e);
        }
    }

    /**
     * The terms of {@code dir} when it holds this patch's, verified; null when it holds none, another patch's or
     * N's, or damaged ones.
     *
     * @param notices where to say what is damaged (null: say nothing, the caller will look again under the lock)
     */
    private static Result reuse(Path dir, String sha, int n, boolean loadTerms, Reporter notices) {
        TermSidecar existing;
        try {
            existing = TermStore.readSidecar(dir);
        } catch (TermStore.Damaged e) {
            notify(notices, e.getMessage());
            return null;
        }
        if (existing == null) {
            if (Files.isRegularFile(dir.resolve(TermStore.DATA_FILE))) {
                notify(notices, dir.resolve(TermStore.DATA_FILE) + " has no " + TermStore.SIDECAR_FILE
                        + " beside it (an interrupted write)");
            }
            return null;
        }
        if (!sha.equals(existing.patch().sha256()) || existing.highestOrder() != n) {
            return null; // another patch or N: replaced
        }
        try {
            if (loadTerms) {
                return new Result(TermStore.read(dir, existing), existing, dir, true);
            }
            TermStore.verify(dir, existing);
            return new Result(null, existing, dir, true);
        } catch (TermStore.Damaged e) {
            notify(notices, e.getMessage());
            return null;
        }
    }

    private static void notify(Reporter notices, String damage) {
        if (notices != null) {
            notices.warn(damage + ": recomputing");
        }
    }

    /** The terms, once the heap is known to hold them. */
    private static TaylorTerms compute(Request request, int n, Reporter reporter) {
        HeightField field = request.meanSubtracted();
        TaylorTermComputer.memory(field.rows(), field.cols(), n).require(String.format(Locale.ROOT,
                "precomputing %d Taylor terms of a %dx%d patch", n + 1, field.cols(), field.rows()),
                "ask for fewer terms or crop the patch");
        return TaylorTermComputer.compute(field, n, reporter);
    }

    /** The reason of an I/O failure in words (NIO's messages are often just the path). */
    static String reason(IOException e) {
        if (e instanceof java.nio.file.AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof java.nio.file.FileSystemException f && f.getReason() != null) {
            return f.getReason();
        }
        if (e instanceof java.nio.file.FileSystemException) {
            return e.getClass().getSimpleName().replace("Exception", "").replaceAll("([a-z])([A-Z])", "$1 $2")
                    .toLowerCase(Locale.ROOT) + ": " + e.getMessage();
        }
        return String.valueOf(e.getMessage());
    }

    /** What {@link #intoThesisFolder} did. */
    public record ThesisResult(int termCount, Path dir, boolean reused) {
    }

    /**
     * Precomputes into {@code dir} in the thesis' Octave layout ({@link ThesisFormat}) unless it already holds
     * the same terms: a diffract.json with the same patch hash and N, and all term files of the right size.
     * Writers hold the folder's lock, as for the native format.
     */
    public static ThesisResult intoThesisFolder(Request request, Path dir, Reporter reporter) {
        TermSidecar.Selection selection = select(request, reporter);
        int n = highestOrderOf(request, selection);
        HeightField field = request.meanSubtracted();
        String sha = field.contentSha256();
        try (FolderLock lock = FolderLock.acquire(dir, reporter)) {
            ThesisExtras existing;
            try {
                existing = ThesisReader.readExtras(dir);
            } catch (UserInputException e) {
                reporter.warn(e.getMessage() + ": recomputing");
                existing = null;
            }
            if (existing != null && sha.equals(existing.patchSha256()) && existing.highestOrder() == n
                    && ThesisReader.filesLookComplete(dir, existing)) {
                return new ThesisResult(n + 1, dir, true);
            }
            lock.removeStaleTemporaries();
            TaylorTerms terms = compute(request, n, reporter);
            ThesisFormat.write(dir, terms, new ThesisFormat.Provenance(request.source(), sha, request.maxHeightUm()),
                    reporter);
        } catch (IOException e) {
            throw new UserInputException("cannot write thesis-format terms to " + dir + ": " + reason(e), e);
        }
        return new ThesisResult(n + 1, dir, false);
    }

    /** The disk cache's kind of the Taylor terms: one folder entry per (patch content, N). */
    public static final String CACHE_KIND = "terms";

    /**
     * Terms from the user's disk cache ({@link DiskCache#user}), computed on first use. A damaged entry is recomputed
     * (with a warning); a cache that cannot be written means the terms are computed in memory (with a note), not a
     * refusal; a disabled cache is neither read nor written.
     */
    public static TaylorTerms cached(Request request, Reporter reporter) {
        DiskCache cache = DiskCache.user();
        if (!cache.enabled()) {
            TermSidecar.Selection selection = select(request, reporter);
            return compute(request, highestOrderOf(request, selection), reporter);
        }
        TermSidecar.Selection selection = select(request, Reporter.SILENT);
        int n = highestOrderOf(request, selection);
        String sha = request.meanSubtracted().contentSha256();
        Path dir = cache.folderEntry(CACHE_KIND, sha.substring(0, 24) + "-n" + n);
        Result result = intoFolder(request, dir, true, true, reporter);
        if (result.reused()) {
            cache.touch(dir);
        } else if (result.sidecar() != null && cache.stored(dir, "the Taylor terms", reporter)) {
            reporter.info("cached Taylor terms in " + dir);
        }
        return result.terms();
    }

    private static int highestOrderOf(Request request, TermSidecar.Selection selection) {
        if (request.highestOrder() != null) {
            return request.highestOrder();
        }
        double x = selection.maxPhase();
        return TaylorBound.termsForTolerance(x, request.tolerance());
    }

}
