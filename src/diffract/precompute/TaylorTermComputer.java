package diffract.precompute;

import diffract.optics.patches.HeightField;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.PhaseCentres;
import diffract.optics.numerics.ShiftedDft;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.MemoryEstimate;
import diffract.util.Reporter;
import pl.edu.icm.jlargearrays.ConcurrencyUtils;

/**
 * Thesis Algorithm 1 (003 section 1.1) with JTransforms in place of Matlab:
 * {@code DFT_n = fftshift(ifft2((i h)^n))}, n = 0..N, for a mean-subtracted height field h in micrometres
 * (see {@link ShiftedDft} for the transform's sign, scale and shift). The powers (i h)^n are formed by repeated
 * multiplication in double precision; each transformed term is rounded once to float32 for storage.
 */
public final class TaylorTermComputer {
    private TaylorTermComputer() {
    }

    /**
     * The heap {@link #compute} holds at its peak: the float32 terms, (N + 1) x rows x cols x 8 bytes, and three
     * double complex arrays of the patch (the power (i h)^n, its transform, the fftshifted copy), 48 bytes per
     * sample.
     */
    public static MemoryEstimate memory(int rows, int cols, int highestOrder) {
        long samples = (long) rows * cols;
        return MemoryEstimate.of((highestOrder + 1) + " Taylor terms of " + cols + "x" + rows,
                        8L * samples * (highestOrder + 1))
                .plus("FFT work arrays", 48L * samples);
    }

    /** All terms 0..highestOrder as float32, with progress per term. */
    public static TaylorTerms compute(HeightField meanSubtracted, int highestOrder, Reporter reporter) {
        return computeAroundPhase(meanSubtracted, 0.0, highestOrder, reporter);
    }

    /**
     * The terms of the expansion around every centre of {@code centres}:
     * E_{j,n} = fftshift(ifft2(exp(i a_j h) (i h)^n)), n = 0..centres.highestOrder(), as float32 like the thesis'
     * terms (which are the centre a_0 = 0). Progress per centre.
     */
    public static PhaseCentredTerms computeCentred(HeightField meanSubtracted, PhaseCentres centres,
                                                   Reporter reporter) {
        TaylorTerms[] perCentre = new TaylorTerms[centres.centreCount()];
        for (int j = 0; j < perCentre.length; j++) {
            perCentre[j] = computeAroundPhase(meanSubtracted, centres.centrePerUm(j), centres.highestOrder(),
                    Reporter.SILENT);
            reporter.progress("phase-centred terms, " + centres.centreCount() + " centres x "
                    + centres.ordersPerCentre() + " orders", (j + 1) / (double) perCentre.length);
        }
        return new PhaseCentredTerms(centres, perCentre);
    }

    /**
     * fftshift(ifft2(exp(i a_j h) (i h)^n)) for n = 0..highestOrder; at a_j = 0 the start is exactly 1 + 0i, so
     * this is Algorithm 1 bit for bit.
     */
    private static TaylorTerms computeAroundPhase(HeightField meanSubtracted, double centrePerUm, int highestOrder,
                                                  Reporter reporter) {
        if (highestOrder < 0) {
            throw new IllegalArgumentException("the highest Taylor order must be >= 0, got " + highestOrder);
        }
        int rows = meanSubtracted.rows();
        int cols = meanSubtracted.cols();
        double[] h = meanSubtracted.heightsUm();
        ShiftedDft.Plan plan = new ShiftedDft.Plan(rows, cols);
        double[] power = PhaseCentres.centreField(h, centrePerUm); // exp(i a_j h) (i h)^0
        double[] work = new double[power.length];
        float[][] terms = new float[highestOrder + 1][];
        String task = "precompute " + rows + "x" + cols + ", terms 0.." + highestOrder;
        reporter.progress(task, 0);
        for (int n = 0; n <= highestOrder; n++) {
            if (n > 0) {
                PhaseCentres.multiplyByIH(power, h);
            }
            System.arraycopy(power, 0, work, 0, power.length);
            plan.inverseInPlace(work);
            terms[n] = fftshiftToFloat(work, rows, cols);
            reporter.progress(task, (n + 1) / (double) (highestOrder + 1));
        }
        return new TaylorTerms(rows, cols, meanSubtracted.pixelSizeXUm(), meanSubtracted.pixelSizeYUm(),
                meanSubtracted.maxAbsHeightUm(), terms);
    }

    /** One term in double precision, fftshifted, interleaved Re/Im: the yardstick for tests. */
    public static double[] termInDouble(HeightField meanSubtracted, int n) {
        double[] h = meanSubtracted.heightsUm();
        double[] a = new double[2 * h.length];
        for (int i = 0; i < h.length; i++) {
            a[2 * i] = 1.0;
        }
        for (int k = 0; k < n; k++) {
            PhaseCentres.multiplyByIH(a, h);
        }
        return ShiftedDft.inverse(a, meanSubtracted.rows(), meanSubtracted.cols());
    }

    private static float[] fftshiftToFloat(double[] a, int rows, int cols) {
        double[] shifted = ShiftedDft.fftshift(a, rows, cols);
        float[] out = new float[shifted.length];
        for (int i = 0; i < out.length; i++) {
            out[i] = (float) shifted[i];
        }
        return out;
    }

    /** JTransforms keeps a thread pool alive that delays JVM exit by 60 s; the CLI calls this before exiting. */
    public static void shutdownThreadPool() {
        ConcurrencyUtils.shutdownThreadPoolAndAwaitTermination();
    }
}
