package diffract.optics;

import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.OrderWeights;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.Float32Cancellation;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.PhaseCentres;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;

import java.util.Locale;
import java.util.function.BiFunction;

/**
 * Which Taylor expansion a scene is evaluated with: the thesis' series around 0 over the precomputed
 * terms, or, when {@link Float32Cancellation} says that series cannot reach {@link Float32Cancellation#TOLERANCE_IN_P}
 * for this patch (tall structures, short wavelengths), the phase-centred expansion ({@link PhaseCentres}), which is
 * accurate at every height. A scene whose phase-centred terms would not fit {@link #MAX_CENTRED_BYTES} or
 * {@link #MAX_CENTRED_LAYERS} keeps the plain series and says so.
 */
public final class TaylorEvaluation {
    /**
     * GL 4.5 guarantees 2048 texture-array layers (GL 3.3 only 256, but every current driver, llvmpipe included,
     * offers 2048); the centres of a 2 um patch at 380 nm need 270.
     */
    public static final int MAX_CENTRED_LAYERS = 2048;
    /** 1 GiB of RG32F terms (GPU texture or CPU arrays): a 512 x 512 patch of 2 um, 270 layers, needs 540 MiB. */
    public static final long MAX_CENTRED_BYTES = 1L << 30;

    private final TaylorTerms plain;
    private final PhaseCentredTerms centred;
    /** The rigorous orders the lobes method takes ({@link OrderWeights#RIGOROUS}), or null. */
    private OrderCorrection orders;

    private TaylorEvaluation(TaylorTerms plain, PhaseCentredTerms centred) {
        this.plain = plain;
        this.centred = centred;
    }

    /** The thesis' series over these terms. */
    public static TaylorEvaluation plain(TaylorTerms terms) {
        return new TaylorEvaluation(terms, null);
    }

    /** The phase-centred expansion over these terms, without the thesis' terms ({@link #plainTerms()} is null). */
    public static TaylorEvaluation phaseCentred(PhaseCentredTerms terms) {
        return new TaylorEvaluation(null, terms);
    }

    /**
     * Decides for a scene and computes the centred terms when they are needed (with progress).
     *
     * @param centredTerms computes the terms of the centres: {@code TaylorTermComputer::computeCentred} (the
     *                     optics package does no FFTs of its own)
     * @param shortestLambdaNm the shortest wavelength the scene renders
     */
    public static TaylorEvaluation choose(TaylorExpansion mode, HeightField meanSubtracted, TaylorTerms plainTerms,
                                          int highestOrder, double shortestLambdaNm,
                                          BiFunction<HeightField, PhaseCentres, PhaseCentredTerms> centredTerms,
                                          Reporter reporter) {
        double a = 2 * 2 * Math.PI / (shortestLambdaNm * 1e-3); // k |w| with |w| = 2, the largest phase factor
        double x = a * meanSubtracted.maxAbsHeightUm();
        double plainError = Float32Cancellation.plainSeriesError(plainTerms, highestOrder, a);
        if (mode == TaylorExpansion.PLAIN || (mode == TaylorExpansion.AUTO && plainError <= Float32Cancellation.TOLERANCE_IN_P)) {
            if (plainError > Float32Cancellation.TOLERANCE_IN_P) {
                // the plain series was asked for (or the calibrated auto variant's path): the centred one avoids it
                reporter.warn(plainWarning(plainError, shortestLambdaNm, x, highestOrder) + "; the phase-centred"
                        + " expansion avoids it, as do a longer shortest wavelength or a lower patch");
            }
            return plain(plainTerms);
        }
        PhaseCentres centres = PhaseCentres.forPatch(meanSubtracted.maxAbsHeightUm(), shortestLambdaNm);
        long bytes = centres.bytesRg32f(meanSubtracted.rows(), meanSubtracted.cols());
        if (bytes > MAX_CENTRED_BYTES || centres.layerCount() > MAX_CENTRED_LAYERS) {
            String size = String.format(Locale.ROOT, "the phase-centred expansion would need %d centres x %d orders"
                    + " = %d layers of %dx%d (%.0f MiB, limits %d layers, %d MiB)", centres.centreCount(),
                    centres.ordersPerCentre(), centres.layerCount(), meanSubtracted.cols(), meanSubtracted.rows(),
                    bytes / 1048576.0, MAX_CENTRED_LAYERS, MAX_CENTRED_BYTES >> 20);
            if (mode == TaylorExpansion.CENTRED) {
                throw new InvalidSettingException(Quantity.EXPANSION, size + "; use a longer shortest wavelength or a "
                        + "smaller patch");
            }
            // auto is in effect and chose the plain series: only a shorter reach or a lower patch helps
            reporter.warn(size + "; " + plainWarning(plainError, shortestLambdaNm, x, highestOrder)
                    + "; a longer shortest wavelength or a lower patch avoids it");
            return plain(plainTerms);
        }
        reporter.info(String.format(Locale.ROOT, "phase-centred Taylor expansion: x = k|w|max|h| = %.1f at %.0f nm"
                + " (the plain series of %d terms would err by ~%.2g in P); %d centres x %d orders, %.1f MiB",
                x, shortestLambdaNm, highestOrder + 1, plainError, centres.centreCount(), centres.ordersPerCentre(),
                bytes / 1048576.0));
        return new TaylorEvaluation(plainTerms, centredTerms.apply(meanSubtracted, centres));
    }

    private static String plainWarning(double error, double shortestLambdaNm, double x, int highestOrder) {
        return String.format(Locale.ROOT, "the float32 Taylor sum (%d terms) may err by up to %.2g in P (|P| <= 1)"
                + " at %.0f nm (x = k|w|max|h| = %.1f): dim orders will be rounding noise", highestOrder + 1, error,
                shortestLambdaNm, x);
    }

    public boolean isPhaseCentred() {
        return centred != null;
    }

    /** The thesis' terms (present unless made by {@link #phaseCentred}). */
    public TaylorTerms plainTerms() {
        return plain;
    }

    /** These terms with the patch's table of rigorous orders, for the lobes method on the GPU. */
    public TaylorEvaluation withOrders(OrderCorrection table) {
        TaylorEvaluation e = new TaylorEvaluation(plain, centred);
        e.orders = table;
        return e;
    }

    /** The table of rigorous orders the lobes take, where the settings ask for it. */
    public java.util.Optional<OrderCorrection> orders() {
        return java.util.Optional.ofNullable(orders);
    }

    /** The phase-centred terms, or null on the plain path. */
    public PhaseCentredTerms centredTerms() {
        return centred;
    }

    /** The CPU BRDF of a Taylor variant on this path. */
    public DiffractionBrdf brdf(BrdfSettings settings, HeightField meanSubtracted) {
        return centred != null ? DiffractionBrdf.createPhaseCentred(settings, centred).withOrdersOf(meanSubtracted, settings)
                : DiffractionBrdf.create(settings, meanSubtracted, plain);
    }

    /** "plain" or "centred (J x N)", for tables and logs. */
    public String describe() {
        return centred == null ? "plain" : String.format(Locale.ROOT, "centred (%d x %d)",
                centred.centres().centreCount(), centred.centres().ordersPerCentre());
    }
}
