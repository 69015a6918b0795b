package diffract.optics.spectra;

/**
 * A Taylor-series spectrum read through a window over the DFT texels ({@link WindowedTaylorSum}), with the lookup of
 * 003 eq. 1.8: s = (u L_x / lambda, v L_y / lambda) texels from the centre texel, L = N dH the patch extent, and
 * the Taylor factor a = k w. The variants differ in the window (Gaussian or sinc) and in a replication factor
 * (PQ's Dirichlet kernel; 1 otherwise).
 */
abstract class WindowedTaylorSpectrum implements PatchSpectrum {
    final WindowedTaylorSum sum;

    WindowedTaylorSpectrum(WindowedTaylorSum sum) {
        this.sum = sum;
    }

    @Override
    public final double extentXUm() {
        return sum.extentXUm();
    }

    @Override
    public final double extentYUm() {
        return sum.extentYUm();
    }

    @Override
    public final double power(double u, double v, double w, double lambdaUm) {
        double sx = u * extentXUm() / lambdaUm; // eq. 1.8
        double sy = v * extentYUm() / lambdaUm;
        return sum.power(sx, sy, 2.0 * Math.PI / lambdaUm * w) * replicationFactor(sx, sy);
    }

    /** |p + i q|^2 of the replicas at lookup (sx, sy), normalised to 1 at the texel centres; 1 for one patch. */
    double replicationFactor(double sx, double sy) {
        return 1.0;
    }
}
