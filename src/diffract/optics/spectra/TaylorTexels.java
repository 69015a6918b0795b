package diffract.optics.spectra;

/**
 * {@link TexelCoefficients} of the thesis' series over the float32 terms, T_m(a) = sum_{n=0}^{N} a^n / n! DFT_n(m)
 * with c_n = c_{n-1} a / n (what {@code taylorSumAt} in {@code diffraction_common.glsl} sums), or around the nearest
 * phase centre a_j: sum_n (a - a_j)^n / n! E_{j,n}(m) ({@link PhaseCentredSpectrum}, {@code taylor_centred.glsl}).
 * Sums in double.
 */
public final class TaylorTexels implements TexelCoefficients {
    private final TaylorTerms[] perCentre;
    private final PhaseCentres centres;
    private final int highestOrder;

    /** The plain series, orders 0..highestOrder. */
    public TaylorTexels(TaylorTerms terms, int highestOrder) {
        if (highestOrder < 0 || highestOrder > terms.highestOrder()) {
            throw new IllegalArgumentException("Taylor order " + highestOrder + " requested, the terms hold 0.."
                    + terms.highestOrder());
        }
        this.perCentre = new TaylorTerms[] {terms};
        this.centres = null;
        this.highestOrder = highestOrder;
    }

    /** The phase-centred expansion, every order of every centre. */
    public TaylorTexels(PhaseCentredTerms terms) {
        this.centres = terms.centres();
        this.perCentre = new TaylorTerms[centres.centreCount()];
        for (int j = 0; j < perCentre.length; j++) {
            perCentre[j] = terms.aroundCentre(j);
        }
        this.highestOrder = centres.highestOrder();
    }

    @Override
    public double extentXUm() {
        return perCentre[0].cols() * perCentre[0].pixelSizeXUm();
    }

    @Override
    public double extentYUm() {
        return perCentre[0].rows() * perCentre[0].pixelSizeYUm();
    }

    @Override
    public int rows() {
        return perCentre[0].rows();
    }

    @Override
    public int cols() {
        return perCentre[0].cols();
    }

    @Override
    public double maxAbsHeightUm() {
        return perCentre[0].maxAbsHeightUm();
    }

    @Override
    public Texel texel(int mx, int my) {
        TaylorTerms first = perCentre[0];
        if (!TexelCoefficients.inBand(mx, my, first.rows(), first.cols())) {
            return null;
        }
        int index = 2 * ((my + first.centreRow()) * first.cols() + mx + first.centreCol());
        return new Texel() {
            private int cachedCentre = -1;
            private final double[] re = new double[highestOrder + 1];
            private final double[] im = new double[highestOrder + 1];

            @Override
            public void sum(double a, double[] out, boolean derivative) {
                int j = centres == null ? 0 : centres.nearestCentre(a);
                if (j != cachedCentre) {
                    for (int n = 0; n <= highestOrder; n++) {
                        float[] term = perCentre[j].termUnsafe(n);
                        re[n] = term[index];
                        im[n] = term[index + 1];
                    }
                    cachedCentre = j;
                }
                double x = centres == null ? a : a - centres.centrePerUm(j);
                double c = 1.0;
                double sumRe = re[0];
                double sumIm = im[0];
                double dRe = 0;
                double dIm = 0;
                for (int n = 1; n <= highestOrder; n++) {
                    if (derivative) {
                        dRe += c * re[n];
                        dIm += c * im[n];
                    }
                    c *= x / n;
                    sumRe += c * re[n];
                    sumIm += c * im[n];
                }
                out[0] = sumRe;
                out[1] = sumIm;
                if (derivative) {
                    out[2] = dRe;
                    out[3] = dIm;
                }
            }
        };
    }
}
