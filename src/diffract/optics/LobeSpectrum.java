package diffract.optics;

import diffract.colour.HatFilteredSpectrum;
import diffract.colour.MirrorNormalisation;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.DiscFootprint;
import diffract.optics.illumination.Footprint;
import diffract.optics.illumination.LobeGeometry;
import diffract.optics.lobes.GaussianLobes;
import diffract.optics.lobes.LobeWeightTable;
import diffract.optics.numerics.Covariance2;
import diffract.optics.numerics.GaussHermite;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.spectra.TaylorTexels;
import diffract.optics.spectra.TexelCoefficients;
import diffract.optics.windows.CoherenceWindow;

/**
 * The lobes method: the windowed spectrum's Gaussian lobes ({@link GaussianLobes}), each widened by the pixel's
 * footprint and the light and integrated over wavelength by a rule fitted to the lobe (docs/design/filtering.md, section
 * 4). The CPU mirror of {@code shaders/diffraction/lobes.frag}, step for step, in double.
 *
 * <p>Per fragment, with (u, v, w) at the footprint's centre:
 * <ol>
 *   <li>March over the lobe centres c near the segment s(lambda) = (u L_x, v L_y) / lambda, lambda in the band,
 *       along its major axis; for each c the wavelengths at which its centre mu_c(lambda) = lambda (c_x / L_x,
 *       c_y / L_y) comes within reach of the footprint (the box plus {@link LobeQuadrature#reachSigmas} of the
 *       widened lobe's standard deviation) follow from a linear inequality per axis; a lobe out of reach is skipped
 *       before its terms are read.</li>
 *   <li>A lobe's terms are read once; its weight W_c(k w) (|T_m|^2 without pairs) is evaluated at every node.</li>
 *   <li>Nodes: lambda_j = lambda_min + j h inside that interval, h = the passage's width in nanometres (the lobe's
 *       widened standard deviation over the speed |d mu / d lambda|) over {@link LobeQuadrature#nodesPerSigma},
 *       rounded down to 1, 2, 4, 8 or 16 nm and at most {@link LobeQuadrature#maxStepNm}, or any spacing below
 *       1 nm; weights of {@link HatFilteredSpectrum}. A lobe that does not move (c = 0) gets the widest step.</li>
 *   <li>The lobe at each node averaged over the footprint ({@link LobeGeometry}): a BRDF-map pixel's box exactly
 *       (erf per axis) with the light's Gaussian folded into each axis (its off-axis part by
 *       {@link LobeQuadrature#lightNodes} Gauss-Hermite nodes), a surface pixel as a Gaussian.</li>
 * </ol>
 * The gain factor, the shadowing and w are the caller's, at the footprint's centre. Each call allocates its own
 * state: thread-safe.
 */
public final class LobeSpectrum {
    /**
     * The most wavelength nodes one lobe gets when its spacing is below 1 nm: a guard only (the default quadrature
     * asks for about ten; the shader's bound is 512, which only fine test quadratures exceed).
     */
    static final int MAX_NODES = 1 << 20;

    private final GaussianLobes lobes;
    private final HatFilteredSpectrum spectral;
    /** {@link HatFilteredSpectrum#bandWeight}: what a lobe of peak average 1 adds at most over any passage. */
    private final double bandWeight;
    private final LobeQuadrature quadrature;
    private final double extentXUm;
    private final double extentYUm;
    private final double sigmaFPerUm;
    private final double lambdaMinNm;
    private final double lambdaMaxNm;
    private final boolean fastErf;
    /** The tabulated weights of whole-texel lobes, or null (pairs, or a weight tolerance of 0). */
    private final LobeWeightTable table;
    /** Whether the march skips blocks of texels by their bound ({@link #marchBlocks}); off only to test it. */
    private boolean blockMarch = true;
    /** The texels' sums where lobes are at least as wide as a cell ({@link LobeSumTable#applies}), or null. */
    private final LobeSumTable sums;
    /**
     * The rigorous orders' ratios each lobe's weight is multiplied by ({@link OrderCorrection}), for light from
     * {@link #correctionWi}; null: the scalar weights.
     */
    private final OrderCorrection correction;
    private final Direction correctionWi;

    /**
     * Over the band and with the mirror's normalisation of {@code spectral} (its step is the quadrature's).
     *
     * @param fastErf the shader's erf (Abramowitz and Stegun 7.1.26) instead of the accurate one
     */
    LobeSpectrum(TexelCoefficients coefficients, CoherenceWindow window, SpectralSettings spectral,
                 LobeQuadrature quadrature, boolean fastErf) {
        double lambdaMinNm = spectral.lambdaMinNm();
        double lambdaMaxNm = spectral.lambdaMaxNm();
        this.extentXUm = coefficients.extentXUm();
        this.extentYUm = coefficients.extentYUm();
        this.lobes = new GaussianLobes(coefficients, window.sigmaTexels(extentXUm), window.sigmaTexels(extentYUm),
                window.averaged() ? GaussianLobes.WHOLE_TEXELS : quadrature.pairThreshold());
        this.spectral = new HatFilteredSpectrum(lambdaMinNm, lambdaMaxNm, spectral.normalisation());
        this.bandWeight = this.spectral.bandWeight();
        this.quadrature = quadrature;
        this.sigmaFPerUm = window.sigmaFrequencyPerUm();
        this.lambdaMinNm = lambdaMinNm;
        this.lambdaMaxNm = lambdaMaxNm;
        this.fastErf = fastErf;
        this.table = quadrature.weightTolerance() > 0 && !lobes.hasPairs()
                ? new LobeWeightTable(coefficients, lambdaMinNm, quadrature.weightTolerance())
                : null;
        this.sums = table != null && LobeSumTable.applies(window, quadrature, extentXUm, extentYUm)
                ? new LobeSumTable(table, window.sigmaTexels(extentXUm), window.sigmaTexels(extentYUm))
                : null;
        this.correction = null;
        this.correctionWi = null;
    }

    /**
     * A lobe's weight W_c(a) = W_c(k w) at the wavelength: from the table, or summed from its texels' coefficients;
     * times its order's rigorous ratio there where the orders correct it.
     */
    private interface Weight {
        double at(double phase, double lambdaNm);
    }

    /** The lobe centred at (twiceCx, twiceCy) / 2 as a weight, or null when no stored texel or kept pair makes it. */
    private Weight weightOf(int twiceCx, int twiceCy) {
        Weight scalar;
        if (table != null) {
            int col = twiceCx / 2 + table.cols() / 2;
            int row = twiceCy / 2 + table.rows() / 2;
            if (!TexelCoefficients.inBand(twiceCx / 2, twiceCy / 2, table.rows(), table.cols())) {
                return null;
            }
            scalar = (a, lambdaNm) -> table.weight(col, row, a);
        } else {
            GaussianLobes.Lobe lobe = lobes.lobe(twiceCx, twiceCy);
            if (lobe == null) {
                return null;
            }
            scalar = (a, lambdaNm) -> lobe.weight(a);
        }
        if (correction == null) {
            return scalar;
        }
        // whole texels only: the correction applies where the window is averaged over its position
        int mx = twiceCx / 2;
        int my = twiceCy / 2;
        return (a, lambdaNm) -> scalar.at(a, lambdaNm) * correction.ratio(mx, my, lambdaNm, correctionWi);
    }

    /** How much more than its scalar weight a lobe can carry: the orders' largest ratio, else 1. */
    private double ordersFactor() {
        return correction == null ? 1 : correction.largest();
    }

    /**
     * Whether the lobe of whole texel (twiceCx, twiceCy) / 2, over wavelengths [fromNm, toNm] at w, can add at least
     * the cutoff to the pixel at (u, v): its table bound over those phases times the largest spectral weight per
     * nanometre of its nodes ({@link HatFilteredSpectrum#maxDensity(double, double)}) times a bound on the lobe's
     * footprint average summed over its nodes ({@link #passageMass}), or, where less, its peak average times the
     * band's weight ({@link HatFilteredSpectrum#bandWeight}).
     */
    private boolean reaches(int twiceCx, int twiceCy, double u, double v, double w, double fromNm, double toNm,
                            Shape shape) {
        if (table == null || quadrature.cutoff() == 0) {
            return true;
        }
        if (!TexelCoefficients.inBand(twiceCx / 2, twiceCy / 2, table.rows(), table.cols())) {
            return false;
        }
        return bound(twiceCx, twiceCy, u, v, w, fromNm, toNm, shape) >= quadrature.cutoff();
    }

    /** The bound {@link #reaches} compares with the cutoff, of a texel in the table's band. */
    private double bound(int twiceCx, int twiceCy, double u, double v, double w, double fromNm, double toNm,
                         Shape shape) {
        return ordersFactor() * table.bound(twiceCx / 2 + table.cols() / 2, twiceCy / 2 + table.rows() / 2,
                phaseLo(w, toNm, shape), phaseHi(w, fromNm, shape)) * Math.min(shape.peak * bandWeight, spectral.maxDensity(fromNm, toNm)
                * passageMass(0.5 * twiceCx / extentXUm, 0.5 * twiceCy / extentYUm, u, v, fromNm, toNm, shape));
    }

    /** The smallest |k w| of a passage ending at toNm: a disc's directions move w by at most sin R about its centre's. */
    private static double phaseLo(double w, double toNm, Shape shape) {
        double spread = shape.disc == null ? 0 : shape.disc.semiAxisE();
        return 2 * Math.PI * 1e3 * Math.max(0, Math.abs(w) - spread) / toNm;
    }

    /** The largest |k w| of a passage starting at fromNm. */
    private static double phaseHi(double w, double fromNm, Shape shape) {
        double spread = shape.disc == null ? 0 : shape.disc.semiAxisE();
        return 2 * Math.PI * 1e3 * (Math.abs(w) + spread) / fromNm;
    }

    /**
     * {@link #passageMass} of every lobe centred in the box [cx0, cx1] x [cy0, cy1] over [fromNm, toNm]: the line form
     * with the box's nearest centre to the origin (the smallest |c|), the smallest distance of the lines through the
     * origin and its corners from (u, v) (0 where they pass on both sides; the extreme lines through a box pass its
     * corners) less the footprint box's half-diagonal.
     */
    private double blockPassageMass(double cx0, double cx1, double cy0, double cy1, double u, double v,
                                    double fromNm, double toNm, Shape shape) {
        double c = Math.hypot(Math.max(cx0, Math.min(0, cx1)), Math.max(cy0, Math.min(0, cy1)));
        double[] xs = {cx0, cx1, cx1, cx0};
        double[] ys = {cy0, cy0, cy1, cy1};
        double across = Double.POSITIVE_INFINITY;
        boolean below = false;
        boolean above = false;
        for (int corner = 0; corner < 4; corner++) {
            double cross = u * ys[corner] - v * xs[corner];
            below |= cross <= 0;
            above |= cross >= 0;
            across = Math.min(across, Math.abs(cross) / Math.max(Math.hypot(xs[corner], ys[corner]), 1e-300));
        }
        across = below && above ? 0 : Math.max(0, across - Math.hypot(shape.hx, shape.hy));
        return lineMass(c, across, fromNm, toNm, shape);
    }

    /**
     * A bound on sum_j h_j a(lambda_j), the footprint average a of a lobe of peak 1 centred at lambda c (c per um)
     * summed over its nodes (spacing h, nm) in [fromNm, toNm], for a unimodal a: at most the integral plus one node
     * times the largest value. Two bounds, the smaller taken:
     * <ul>
     *   <li>the largest average held over the passage and one node more, peak (to - from + h_max);</li>
     *   <li>without a disc and for c != 0: the lobe (variance at most S = (lambda_to sigma_f)^2 / 2 plus the
     *       footprint Gaussian's largest eigenvalue, peak at most 1) moves along the line lambda c through the
     *       origin, which passes at distance d = |u c_y - v c_x| / |c| from the footprint's centre, d - h_n from its
     *       box (h_n the box's half-width across the line). Its integral along the line is at most sqrt(2 pi S)
     *       e, e = exp(-(d - h_n)^2 / (2 S)), per |c| um of wavelength; its largest value is at most min(peak, e);
     *       and the node spacing is at most sqrt(2 S) / (|c| nodesPerSigma) (the passage's width on its faster axis),
     *       1 nm or the widest step.</li>
     * </ul>
     */
    private double passageMass(double cx, double cy, double u, double v, double fromNm, double toNm, Shape shape) {
        double c = Math.hypot(cx, cy);
        double across = c > 0 ? Math.max(0, (Math.abs(u * cy - v * cx) - shape.hx * Math.abs(cy)
                - shape.hy * Math.abs(cx)) / c) : 0;
        return lineMass(c, across, fromNm, toNm, shape);
    }

    /**
     * The bound of {@link #passageMass} for lobes moving at least at speed c (per um) whose lines pass at least
     * {@code across} from the footprint's box: the line form, or the length form where less (always under a disc, or
     * for a lobe at rest).
     */
    private double lineMass(double c, double across, double fromNm, double toNm, Shape shape) {
        double widestStep = Math.max(1, quadrature.maxStepNm());
        double mass = shape.peak * (toNm - fromNm + widestStep);
        if (shape.disc != null || c == 0) {
            return mass;
        }
        double s = 0.5 * square(toNm * 1e-3 * sigmaFPerUm) + shape.gaussianMax;
        double e = Math.exp(-across * across / (2 * s));
        double step = Math.max(1, Math.min(1e3 * Math.sqrt(2 * s) / (c * quadrature.nodesPerSigma()), widestStep));
        return Math.min(mass, 1e3 * Math.sqrt(2 * Math.PI * s) * e / c + Math.min(shape.peak, e) * step);
    }

    /** This spectrum with every lobe's weight times the rigorous orders' ratio for light from {@code wi}. */
    private LobeSpectrum(LobeSpectrum base, OrderCorrection correction, Direction wi) {
        this.lobes = base.lobes;
        this.spectral = base.spectral;
        this.bandWeight = base.bandWeight;
        this.quadrature = base.quadrature;
        this.extentXUm = base.extentXUm;
        this.extentYUm = base.extentYUm;
        this.sigmaFPerUm = base.sigmaFPerUm;
        this.lambdaMinNm = base.lambdaMinNm;
        this.lambdaMaxNm = base.lambdaMaxNm;
        this.fastErf = base.fastErf;
        this.table = base.table;
        this.blockMarch = base.blockMarch;
        // a texel sum adds lobes of many orders under one weight: the corrected lobes are integrated one by one
        this.sums = null;
        this.correction = correction;
        this.correctionWi = wi;
    }

    /**
     * The lobes with the rigorous orders on them ({@link OrderCorrection}): each lobe's weight W_m times its order's
     * ratio at the node's wavelength for light from {@code wi}; the bounds grow by the table's largest ratio. A view:
     * it shares this spectrum's tables.
     */
    public LobeSpectrum withOrders(OrderCorrection orders, Direction wi) {
        return new LobeSpectrum(this, orders, wi);
    }

    /** Over the float32 Taylor terms, the plain series to {@code highestOrder}: what the shader reads. */
    public static LobeSpectrum ofTerms(TaylorTerms terms, int highestOrder, CoherenceWindow window,
                                       SpectralSettings spectral, LobeQuadrature quadrature) {
        return new LobeSpectrum(new TaylorTexels(terms, highestOrder), window, spectral, quadrature, true);
    }

    /** Over the float32 terms of the phase-centred expansion. */
    public static LobeSpectrum ofTerms(PhaseCentredTerms terms, CoherenceWindow window, SpectralSettings spectral,
                                       LobeQuadrature quadrature) {
        return new LobeSpectrum(new TaylorTexels(terms), window, spectral, quadrature, true);
    }

    /** Texel pairs kept per axis (0: whole texels only, what the shader sums). */
    public int pairRadiusX() {
        return lobes.pairRadiusX();
    }

    public int pairRadiusY() {
        return lobes.pairRadiusY();
    }

    public double extentXUm() {
        return extentXUm;
    }

    public double extentYUm() {
        return extentYUm;
    }

    /** The per-fragment shape of the footprint, prepared once. */
    private static final class Shape {
        final double hx;
        final double hy;
        final Covariance2 gaussian; // full when there is no box, else its diagonal part
        final double[] shiftU;      // Gauss-Hermite shifts of the rank-one part (box only)
        final double[] shiftV;
        final double[] shiftWeight;
        final double reachU;
        final double reachV;
        /** The largest average over the footprint a lobe of peak 1 can have (at the longest wavelength). */
        final double peak;
        /** The footprint Gaussian's largest eigenvalue (the whole Gaussian, the rank-one part with a box included). */
        final double gaussianMax;

        /** The disc light the footprint averages over, or null (a point or Gaussian light, in the Gaussian). */
        final DiscFootprint disc;
        /**
         * Variances (u, v) that widen a lobe's passage beyond its own for the node spacing: a disc's box where it has
         * rims, its Gaussian's where it has none (a Gaussian light is in {@link #gaussian} already).
         */
        final double passageU;
        final double passageV;

        Shape(Footprint footprint, LobeQuadrature quadrature, double widestLobeVariance) {
            this(footprint, quadrature, widestLobeVariance, null);
        }

        Shape(Footprint footprint, LobeQuadrature quadrature, double widestLobeVariance, DiscFootprint disc) {
            this.disc = disc;
            hx = footprint.halfWidthU();
            hy = footprint.halfWidthV();
            Covariance2 g = footprint.gaussian();
            gaussianMax = 0.5 * (g.xx() + g.yy()) + Math.hypot(0.5 * (g.xx() - g.yy()), g.xy());
            if (disc != null) {
                gaussian = g;
                shiftU = new double[] {0};
                shiftV = new double[] {0};
                shiftWeight = new double[] {1};
                // rims wherever the disc can be wider than the narrowest blur (the thinner side of the box and the
                // Gaussian, the lobe left out to be safe); else the disc is its Gaussian throughout, reached and
                // sampled as a Gaussian light is
                double narrowest = Math.min(g.xx(), g.yy()) + Math.min(hx * hx, hy * hy) / 3;
                Covariance2 discGaussian = disc.covariance();
                boolean rims = disc.hasRims(narrowest);
                if (rims) {
                    // the box and the disc end where they end (BoxedEdge); the lobe and the Gaussian blur beyond
                    reachU = hx + disc.reach(0) + quadrature.reachSigmas() * Math.sqrt(widestLobeVariance + g.xx());
                    reachV = hy + disc.reach(1) + quadrature.reachSigmas() * Math.sqrt(widestLobeVariance + g.yy());
                    passageU = hx * hx / 3;
                    passageV = hy * hy / 3;
                } else {
                    reachU = hx + quadrature.reachSigmas() * Math.sqrt(widestLobeVariance + g.xx()
                            + discGaussian.xx());
                    reachV = hy + quadrature.reachSigmas() * Math.sqrt(widestLobeVariance + g.yy()
                            + discGaussian.yy());
                    passageU = discGaussian.xx();
                    passageV = discGaussian.yy();
                }
                // the rim's plateau at the disc's densest direction, or the small disc's Gaussian peak (with a box:
                // per axis the box's bound and the widened lobe's, as DiscFootprint.average takes the box with the
                // Gaussian's diagonal), times the bound on the gain relative to the centre's across the disc
                double sigma2 = 2 * widestLobeVariance;
                Covariance2 spread = g.plus(discGaussian);
                Covariance2 s = spread.plus(Covariance2.isotropic(widestLobeVariance));
                double sigma = Math.sqrt(sigma2);
                double gaussianPeak = footprint.hasBox()
                        ? axisPeak(sigma, hx, spread.xx()) * axisPeak(sigma, hy, spread.yy())
                        : sigma2 / (2 * Math.sqrt(s.xx() * s.yy() - s.xy() * s.xy()));
                peak = disc.gainBound() * (rims ? Math.max(Math.PI * sigma2 * disc.peakDensity(), gaussianPeak)
                        : gaussianPeak);
                return;
            }
            passageU = 0;
            passageV = 0;
            if (footprint.hasBox() && !g.isDiagonal()) {
                double[] split = g.diagonalPlusRankOne();
                gaussian = new Covariance2(split[0], 0, split[1]);
                int n = quadrature.lightNodes();
                double[] nodes = GaussHermite.nodes(n);
                double sigma = Math.sqrt(split[4]);
                shiftU = new double[n];
                shiftV = new double[n];
                shiftWeight = GaussHermite.weights(n);
                for (int k = 0; k < n; k++) {
                    shiftU[k] = sigma * nodes[k] * split[2];
                    shiftV[k] = sigma * nodes[k] * split[3];
                }
            } else {
                gaussian = g;
                shiftU = new double[] {0};
                shiftV = new double[] {0};
                shiftWeight = new double[] {1};
            }
            // the full Gaussian's marginals bound the reach on each axis
            reachU = hx + quadrature.reachSigmas() * Math.sqrt(widestLobeVariance + g.xx());
            reachV = hy + quadrature.reachSigmas() * Math.sqrt(widestLobeVariance + g.yy());
            double sigma = Math.sqrt(2 * widestLobeVariance);
            if (hasBox()) {
                // per axis: the box average of the widened lobe is at most the box's (sqrt(pi) sigma_uv / 2h) and
                // the widened peak's (sigma_uv / sqrt(sigma_uv^2 + 2 Sigma_ii)); the light's shifts average these
                peak = axisPeak(sigma, hx, gaussian.xx()) * axisPeak(sigma, hy, gaussian.yy());
            } else {
                double sxx = widestLobeVariance + g.xx();
                double syy = widestLobeVariance + g.yy();
                peak = sigma * sigma / (2 * Math.sqrt(sxx * syy - g.xy() * g.xy()));
            }
        }

        private static double axisPeak(double sigmaUv, double h, double variance) {
            double peak = sigmaUv / Math.sqrt(sigmaUv * sigmaUv + 2 * variance);
            return h > 0 ? Math.min(peak, Math.sqrt(Math.PI) * sigmaUv / (2 * h)) : peak;
        }

        boolean hasBox() {
            return hx > 0 || hy > 0;
        }
    }

    /**
     * XYZ of D65 light diffracted at (u, v, w), averaged over the footprint around (u, v), before the gain factor
     * and shadowing: {X, Y, Z}, D65 white at Y = 1.
     */
    public double[] xyz(double u, double v, double w, Footprint footprint) {
        return xyz(u, v, w, footprint, null);
    }

    /**
     * As {@link #xyz(double, double, double, Footprint)} under a disc light ({@link DiscFootprint}; null: the light is
     * the footprint's Gaussian or none): (u, v, w) at the light's centre, and the result relative to the gain factor
     * and shadowing there, which the disc's directions carry in proportion.
     */
    public double[] xyz(double u, double v, double w, Footprint footprint, DiscFootprint disc) {
        if (sums != null && disc == null && sumsFit(footprint)) {
            return summedXyz(u, v, w, footprint);
        }
        double widest = 0.5 * square(lambdaMaxNm * 1e-3 * sigmaFPerUm);
        Shape shape = new Shape(footprint, quadrature, widest, disc);
        double[] total = new double[3];
        double[] node = new double[3];
        int step = lobes.hasPairs() ? 1 : 2;
        double[] xRange = range(u, shape.reachU, extentXUm, lambdaMinNm * 1e-3, lambdaMaxNm * 1e-3);
        double[] yRange = range(v, shape.reachV, extentYUm, lambdaMinNm * 1e-3, lambdaMaxNm * 1e-3);
        boolean majorIsX = majorIsX(xRange, yRange);
        double[] major = majorIsX ? xRange : yRange;
        if (step == 2 && table != null && blockMarch) {
            marchBlocks(u, v, w, shape, majorIsX, major, node, total);
            return total;
        }
        marchTexels(u, v, shape, step, majorIsX, major, (tx, ty) -> addLobe(tx, ty, u, v, w, shape, node, total));
        return total;
    }

    /** Whether the march runs along x: the longer of the footprint's texel ranges over the band. */
    private static boolean majorIsX(double[] xRange, double[] yRange) {
        return (xRange[1] - xRange[0]) >= (yRange[1] - yRange[0]);
    }

    /** A lobe centre the march reaches, as doubled coordinates. */
    private interface Visit {
        void at(int tx, int ty);
    }

    /**
     * The texels across the major axis (a range in texels, as {@link #range} gives it) whose lobes come within reach
     * of (u, v) for the wavelengths at which the lobes at major coordinate {@code majorTexel} do on the major axis;
     * null for none.
     */
    private double[] minorRange(double majorTexel, double u, double v, Shape shape, boolean majorIsX) {
        double[] along = majorIsX
                ? LobeGeometry.lambdaIntervalNm(majorTexel / extentXUm, 0, u, 0, shape.reachU, 1, lambdaMinNm,
                lambdaMaxNm)
                : LobeGeometry.lambdaIntervalNm(0, majorTexel / extentYUm, 0, v, 1, shape.reachV, lambdaMinNm,
                lambdaMaxNm);
        if (along == null) {
            return null;
        }
        return majorIsX ? range(v, shape.reachV, extentYUm, along[0] * 1e-3, along[1] * 1e-3)
                : range(u, shape.reachU, extentXUm, along[0] * 1e-3, along[1] * 1e-3);
    }

    /** The march over lattice points (step 2: whole texels; 1: pairs' midpoints too) near the segment s(lambda). */
    private void marchTexels(double u, double v, Shape shape, int step, boolean majorIsX, double[] major,
                             Visit visit) {
        for (int tMajor = first(major[0], step); tMajor <= Math.ceil(2 * major[1]); tMajor += step) {
            double[] minor = minorRange(0.5 * tMajor, u, v, shape, majorIsX);
            if (minor == null) {
                continue;
            }
            for (int tMinor = first(minor[0], step); tMinor <= Math.ceil(2 * minor[1]); tMinor += step) {
                visit.at(majorIsX ? tMajor : tMinor, majorIsX ? tMinor : tMajor);
            }
        }
    }

    /**
     * Every whole texel's lobe within reach of (u, v) under a footprint (no disc), without the cutoff: what it adds
     * (its largest channel, integrated as {@link #xyz} integrates it) and the bound the cutoff compares
     * ({@link #reaches}), {added, bound} per lobe. For the tests of the bound.
     */
    java.util.List<double[]> lobeBounds(double u, double v, double w, Footprint footprint) {
        if (table == null) {
            throw new IllegalStateException("the bounds are the weight table's");
        }
        Shape shape = new Shape(footprint, quadrature, 0.5 * square(lambdaMaxNm * 1e-3 * sigmaFPerUm));
        double[] xRange = range(u, shape.reachU, extentXUm, lambdaMinNm * 1e-3, lambdaMaxNm * 1e-3);
        double[] yRange = range(v, shape.reachV, extentYUm, lambdaMinNm * 1e-3, lambdaMaxNm * 1e-3);
        boolean majorIsX = majorIsX(xRange, yRange);
        java.util.List<double[]> out = new java.util.ArrayList<>();
        double[] node = new double[3];
        marchTexels(u, v, shape, 2, majorIsX, majorIsX ? xRange : yRange, (tx, ty) -> {
            double cx = 0.5 * tx / extentXUm;
            double cy = 0.5 * ty / extentYUm;
            double[] interval = LobeGeometry.lambdaIntervalNm(cx, cy, u, v, shape.reachU, shape.reachV, lambdaMinNm,
                    lambdaMaxNm);
            Weight lobe = weightOf(tx, ty);
            if (interval == null || lobe == null
                    || !TexelCoefficients.inBand(tx / 2, ty / 2, table.rows(), table.cols())) {
                return;
            }
            double[] added = new double[3];
            integrate(lobe, cx, cy, u, v, w, shape, interval[0], interval[1], node, added);
            out.add(new double[] {Math.max(added[0], Math.max(added[1], added[2])),
                bound(tx, ty, u, v, w, interval[0], interval[1], shape)});
        });
        return out;
    }

    /** This spectrum, marching texel by texel: the sum {@link #marchBlocks} must equal. */
    LobeSpectrum withoutBlocks() {
        blockMarch = false;
        return this;
    }

    /** Adds the lobe of doubled centre (tx, ty) where it reaches the footprint and the cutoff. */
    private void addLobe(int tx, int ty, double u, double v, double w, Shape shape, double[] node, double[] total) {
        double cx = 0.5 * tx / extentXUm;
        double cy = 0.5 * ty / extentYUm;
        double[] interval = LobeGeometry.lambdaIntervalNm(cx, cy, u, v, shape.reachU, shape.reachV, lambdaMinNm,
                lambdaMaxNm);
        if (interval == null || !reaches(tx, ty, u, v, w, interval[0], interval[1], shape)) {
            return;
        }
        Weight lobe = weightOf(tx, ty);
        if (lobe != null) {
            integrate(lobe, cx, cy, u, v, w, shape, interval[0], interval[1], node, total);
        }
    }

    /**
     * How many times as many texels the order of their bounds must test before rows are taken instead: a row's texel
     * goes through the whole test, while the order rejects a texel outside the segment's reach by its wavelength
     * interval alone. 2 keeps the 52 um scan within 10 % of the order alone and halves a thin segment's time
     * (docs/design/filtering.md).
     */
    public static final int ROWS_FACTOR = 2;

    /**
     * Whether a block that passed its test is marched row by row: where the order of its texels' bounds would test
     * {@link #ROWS_FACTOR} times as many texels as its rows within the segment's reach hold, at most, before the cutoff
     * stops it (its texel in that slot is still above the cutoff). A thin segment crosses a block in a few texels per
     * row, while at a bright display's cutoff nearly all of a block's bounds pass; in a scan's speckle a block passes
     * for a few bright texels, and the order reads those alone.
     *
     * @param rows          the block's rows (along the major axis)
     * @param across        its texels across a row
     * @param passageTexels the segment's reach across the major axis, in texels
     * @param scale         the block's bound per unit of a texel's weight bound
     */
    private boolean byRows(int blockCol, int blockRow, int rows, int across, double passageTexels, double scale) {
        int slots = ROWS_FACTOR * rows * Math.min(across, (int) passageTexels + 2);
        int block = LobeWeightTable.BLOCK;
        return slots < block * block && table.orderedTexel(blockCol, blockRow, slots) >= 0
                && table.orderedBound(blockCol, blockRow, slots) * scale >= quadrature.cutoff();
    }

    /**
     * Blocks the march took row by row and by their texels' bounds, since this spectrum was made (for tests); adders,
     * as the rows of a map share one spectrum across threads.
     */
    final java.util.concurrent.atomic.LongAdder blocksByRows = new java.util.concurrent.atomic.LongAdder();
    final java.util.concurrent.atomic.LongAdder blocksByBound = new java.util.concurrent.atomic.LongAdder();

    /**
     * The march over whole texels in blocks of the weight table ({@link LobeWeightTable#BLOCK}): along the major axis
     * block by block, across it the blocks the footprint's segment can reach there; a block whose bound over the
     * wavelengths any of its lobes comes within reach cannot reach the cutoff is skipped, and in the others its texels
     * are tested as the plain march tests them, either from the largest bound down
     * ({@link LobeWeightTable#orderedTexel}) until the bound left cannot reach the cutoff, or row by row along the
     * major axis, each row's within the segment's reach, whichever tests fewer ({@link #byRows}). The same lobes as
     * the plain march, in the shader's order.
     */
    private void marchBlocks(double u, double v, double w, Shape shape, boolean majorIsX, double[] major,
                             double[] node, double[] total) {
        int block = LobeWeightTable.BLOCK;
        int majorHalf = majorIsX ? table.cols() / 2 : table.rows() / 2;
        int minorHalf = majorIsX ? table.rows() / 2 : table.cols() / 2;
        int majorCount = majorIsX ? table.cols() : table.rows();
        int minorCount = majorIsX ? table.rows() : table.cols();
        double majorExtent = majorIsX ? extentXUm : extentYUm;
        double minorExtent = majorIsX ? extentYUm : extentXUm;
        double majorUv = majorIsX ? u : v;
        double minorUv = majorIsX ? v : u;
        double majorReach = majorIsX ? shape.reachU : shape.reachV;
        double minorReach = majorIsX ? shape.reachV : shape.reachU;
        // the segment's reach across the major axis, in texels at the shortest wavelength
        double passageTexels = 2 * minorReach * minorExtent / (lambdaMinNm * 1e-3);
        // the texels of the plain march, within the grid (a texel outside it has no weight)
        int iFirst = Math.max(first(major[0], 2) / 2, -majorHalf);
        int iLast = Math.min(Math.floorDiv((int) Math.ceil(2 * major[1]), 2), majorCount - 1 - majorHalf);
        for (int bi = Math.floorDiv(iFirst + majorHalf, block); bi <= Math.floorDiv(iLast + majorHalf, block); bi++) {
            int i0 = Math.max(iFirst, bi * block - majorHalf);
            int i1 = Math.min(iLast, bi * block + block - 1 - majorHalf);
            double[] along = LobeGeometry.boxLambdaIntervalNm(i0 / majorExtent, i1 / majorExtent, 0, 0, majorUv, 0,
                    majorReach, 1, lambdaMinNm, lambdaMaxNm);
            if (along == null) {
                continue;
            }
            double[] minor = range(minorUv, minorReach, minorExtent, along[0] * 1e-3, along[1] * 1e-3);
            int kFirst = Math.max(first(minor[0], 2) / 2, -minorHalf);
            int kLast = Math.min(Math.floorDiv((int) Math.ceil(2 * minor[1]), 2), minorCount - 1 - minorHalf);
            for (int bk = Math.floorDiv(kFirst + minorHalf, block); bk <= Math.floorDiv(kLast + minorHalf, block);
                 bk++) {
                int k0 = Math.max(kFirst, bk * block - minorHalf);
                int k1 = Math.min(kLast, bk * block + block - 1 - minorHalf);
                double[] at = majorIsX
                        ? LobeGeometry.boxLambdaIntervalNm(i0 / majorExtent, i1 / majorExtent, k0 / minorExtent,
                        k1 / minorExtent, u, v, shape.reachU, shape.reachV, lambdaMinNm, lambdaMaxNm)
                        : LobeGeometry.boxLambdaIntervalNm(k0 / minorExtent, k1 / minorExtent, i0 / majorExtent,
                        i1 / majorExtent, u, v, shape.reachU, shape.reachV, lambdaMinNm, lambdaMaxNm);
                if (at == null) {
                    continue;
                }
                // at least each texel's reaches(): their passages lie within the block's
                double bound = majorIsX ? table.blockBound(bi, bk, phaseLo(w, at[1], shape), phaseHi(w, at[0], shape))
                        : table.blockBound(bk, bi, phaseLo(w, at[1], shape), phaseHi(w, at[0], shape));
                double mass = majorIsX
                        ? blockPassageMass(i0 / majorExtent, i1 / majorExtent, k0 / minorExtent, k1 / minorExtent, u, v,
                        at[0], at[1], shape)
                        : blockPassageMass(k0 / minorExtent, k1 / minorExtent, i0 / majorExtent, i1 / majorExtent, u, v,
                        at[0], at[1], shape);
                double scale = ordersFactor() * Math.min(shape.peak * bandWeight, spectral.maxDensity(at[0], at[1])
                        * mass);
                if (bound * scale < quadrature.cutoff()) {
                    continue;
                }
                int bc = majorIsX ? bi : bk;
                int br = majorIsX ? bk : bi;
                if (byRows(bc, br, i1 - i0 + 1, k1 - k0 + 1, passageTexels, scale)) {
                    blocksByRows.increment();
                    // each row's texels as the plain march takes them, within the block
                    for (int i = i0; i <= i1; i++) {
                        double[] minorI = minorRange(i, u, v, shape, majorIsX);
                        if (minorI == null) {
                            continue;
                        }
                        int m0 = Math.max(k0, first(minorI[0], 2) / 2);
                        int m1 = Math.min(k1, Math.floorDiv((int) Math.ceil(2 * minorI[1]), 2));
                        for (int m = m0; m <= m1; m++) {
                            addLobe(majorIsX ? 2 * i : 2 * m, majorIsX ? 2 * m : 2 * i, u, v, w, shape, node, total);
                        }
                    }
                    continue;
                }
                blocksByBound.increment();
                // its texels from the largest bound down, until none left can reach the cutoff; those out of reach
                // have no passage (addLobe)
                for (int slot = 0; slot < block * block; slot++) {
                    int offset = table.orderedTexel(bc, br, slot);
                    if (offset < 0 || table.orderedBound(bc, br, slot) * scale < quadrature.cutoff()) {
                        break;
                    }
                    addLobe(2 * (bc * block + offset % block - table.cols() / 2),
                            2 * (br * block + offset / block - table.rows() / 2), u, v, w, shape, node, total);
                }
            }
        }
    }

    /**
     * The footprint's spectrum from the texels' sums ({@link LobeSumTable}): at wavelength nodes lambda_j the lobes'
     * integral over the footprint's box in texels, pi (lambda sigma_f)^2 / (4 h_u h_v) sum_m W_m |box &#8745; cell_m|,
     * weighted by the hat-filtered spectrum. A Gaussian part of the footprint (the light, or a surface pixel's whole
     * footprint) widens the box to the same variance per axis, h^2 + 3 Sigma_ii. The nodes are spaced so that every
     * lobe's passage through the box is seen by {@link LobeQuadrature#sumNodesPerBox} nodes where the box moves fastest
     * (at lambda_min), on the hat levels or below 1 nm, and at most {@link LobeQuadrature#maxStepNm} apart.
     */
    private double[] summedXyz(double u, double v, double w, Footprint footprint) {
        double hu = summedHalfWidthU(footprint);
        double hv = summedHalfWidthV(footprint);
        double shortestUm = lambdaMinNm * 1e-3;
        double spacing = summedSpacingNm(nodeTravel(u, hu, extentXUm, shortestUm, sigmaFPerUm * extentXUm),
                nodeTravel(v, hv, extentYUm, shortestUm, sigmaFPerUm * extentYUm));
        int last = lastNode(lambdaMaxNm, spacing);
        double[] total = new double[3];
        double[] node = new double[3];
        double edgeX = sums.cellsX() - 0.5;
        double edgeY = sums.cellsY() - 0.5;
        for (int j = 0; j <= last; j++) {
            double lambdaNm = lambdaMinNm + j * spacing;
            double lambdaUm = lambdaNm * 1e-3;
            double x0 = (u - hu) * extentXUm / lambdaUm;
            double x1 = (u + hu) * extentXUm / lambdaUm;
            double y0 = (v - hv) * extentYUm / lambdaUm;
            double y1 = (v + hv) * extentYUm / lambdaUm;
            if (x0 >= edgeX || x1 <= -edgeX - 1 || y0 >= edgeY || y1 <= -edgeY - 1) {
                continue; // beyond the grid's texels
            }
            double box = sums.boxSum(x0, x1, y0, y1, 2 * Math.PI / lambdaUm * w);
            double sigmaUv = lambdaUm * sigmaFPerUm;
            spectral.weight(lambdaNm, spacing, node);
            double scale = Math.PI * sigmaUv * sigmaUv / (4 * hu * hv) * box * endWeight(lambdaNm, spacing);
            total[0] += scale * node[0];
            total[1] += scale * node[1];
            total[2] += scale * node[2];
        }
        return total;
    }

    /**
     * The node spacing (nm) one axis allows: the nm in which the box, at lambda_min where it moves fastest, moves by
     * its own width plus a lobe's (two standard deviations, sqrt(2) sigma_f), over the nodes asked per such width.
     */
    private double nodeTravel(double u, double h, double extentUm, double shortestUm, double sigmaTexels) {
        double speed = (Math.abs(u) + h) * extentUm / (shortestUm * shortestUm) * 1e-3; // texels per nm
        double width = 2 * h * extentUm / shortestUm + Math.sqrt(2) * sigmaTexels;
        return width / (quadrature.sumNodesPerBox() * speed);
    }

    /** The texel sums' node spacing from the axes' (nodeTravel): on the hat levels or below 1 nm, at most maxStepNm. */
    private double summedSpacingNm(double travelXNm, double travelYNm) {
        double bandNm = lambdaMaxNm - lambdaMinNm;
        double target = Math.min(Math.min(Math.min(travelXNm, travelYNm), quadrature.maxStepNm()), bandNm);
        return spacingOnLevels(Math.max(target, bandNm / MAX_SUM_NODES));
    }

    /** The box's half-width along u in the texel sums: the footprint's box widened by its Gaussian's variance. */
    private static double summedHalfWidthU(Footprint footprint) {
        return Math.sqrt(square(footprint.halfWidthU()) + 3 * footprint.gaussian().xx());
    }

    private static double summedHalfWidthV(Footprint footprint) {
        return Math.sqrt(square(footprint.halfWidthV()) + 3 * footprint.gaussian().yy());
    }

    /**
     * Whether the texel sums take this footprint: its box spans at least one texel's cell on both axes at every
     * wavelength (at lambda_max, where it is narrowest), so that what it averages is a lobe's mass and centre, which the
     * cells' spread keeps, not the lobe's shape, which only the march over lobes follows (narrower footprints, as a
     * 256 x 256 map's pixels on a 52 um scan, are marched).
     */
    private boolean sumsFit(Footprint footprint) {
        double longestUm = lambdaMaxNm * 1e-3;
        return 2 * summedHalfWidthU(footprint) * extentXUm / longestUm >= 1
                && 2 * summedHalfWidthV(footprint) * extentYUm / longestUm >= 1;
    }

    /**
     * The most wavelength nodes a footprint's sums take (a guard: a 200 um scan needs about 1200 at the default); the
     * shader's define of the same name.
     */
    public static final int MAX_SUM_NODES = 4096;

    /** The lobe centres (texels) one axis can reach over wavelengths [shortest, longest] um: {lo, hi}. */
    private static double[] range(double u, double reach, double extentUm, double shortestUm, double longestUm) {
        double a = (u - reach) * extentUm;
        double b = (u + reach) * extentUm;
        return new double[] {Math.min(a / shortestUm, a / longestUm), Math.max(b / shortestUm, b / longestUm)};
    }

    /** The first doubled centre at or above 2 lo with the lattice's parity (even without pairs). */
    private static int first(double lo, int step) {
        int t = (int) Math.floor(2 * lo);
        return step == 2 && Math.floorMod(t, 2) != 0 ? t + 1 : t;
    }

    /**
     * One lobe's wavelength integral over [from, to] nm, added to total: at every node the footprint's average of the
     * lobe times its weight, from the table at every node, or (no table) summed from the coefficients every
     * {@link LobeQuadrature#weightStepNm} of the passage and at its ends and linearly interpolated between.
     */
    private void integrate(Weight lobe, double cx, double cy, double u, double v, double w, Shape shape,
                           double from, double to, double[] node, double[] total) {
        double spacing = spacingNm(cx, cy, shape, from);
        int j0 = (int) Math.ceil((from - lambdaMinNm) / spacing - 1e-9);
        int j1 = lastNode(to, spacing);
        if (spacing < 1 && j1 - j0 + 1 > MAX_NODES) {
            spacing = Math.min(1.0, (to - from) / (MAX_NODES - 1));
            j0 = (int) Math.ceil((from - lambdaMinNm) / spacing - 1e-9);
            j1 = lastNode(to, spacing);
        }
        if (j1 < j0) {
            return;
        }
        if (shape.disc != null) {
            double[] disc = new double[2];
            for (int j = j0; j <= j1; j++) {
                double lambdaNm = lambdaMinNm + j * spacing;
                double lambdaUm = lambdaNm * 1e-3;
                shape.disc.average(lambdaUm * sigmaFPerUm, lambdaUm * cx, lambdaUm * cy, shape.hx, shape.hy,
                        shape.gaussian, fastErf, disc);
                if (disc[0] == 0) {
                    continue;
                }
                spectral.weight(lambdaNm, spacing, node);
                double scale = weight(lobe, disc[1], lambdaNm) * disc[0] * endWeight(lambdaNm, spacing);
                total[0] += scale * node[0];
                total[1] += scale * node[1];
                total[2] += scale * node[2];
            }
            return;
        }
        double step = table == null ? quadrature.weightStepNm() : 0;
        double first = lambdaMinNm + j0 * spacing;
        double last = lambdaMinNm + j1 * spacing;
        double slowStep = step > 0 && last > first ? (last - first) / Math.max(1, Math.ceil((last - first) / step)) : 0;
        double slowLo = first;
        double slowHi = first;
        double slowAtLo = weight(lobe, w, first);
        double slowAtHi = slowAtLo;
        for (int j = j0; j <= j1; j++) {
            double lambdaNm = lambdaMinNm + j * spacing;
            double weight;
            if (slowStep == 0) {
                weight = j == j0 ? slowAtLo : weight(lobe, w, lambdaNm);
            } else {
                while (lambdaNm > slowHi + 1e-9) {
                    slowLo = slowHi;
                    slowAtLo = slowAtHi;
                    slowHi = Math.min(last, slowLo + slowStep);
                    slowAtHi = weight(lobe, w, slowHi);
                }
                double t = slowHi > slowLo ? (lambdaNm - slowLo) / (slowHi - slowLo) : 0;
                weight = slowAtLo + t * (slowAtHi - slowAtLo);
            }
            double a = averaged(lambdaNm * 1e-3, cx, cy, u, v, shape);
            spectral.weight(lambdaNm, spacing, node);
            double scale = weight * a * endWeight(lambdaNm, spacing);
            total[0] += scale * node[0];
            total[1] += scale * node[1];
            total[2] += scale * node[2];
        }
    }

    /**
     * The last node of a passage that ends at {@code to}: the last within it, or, where it ends at the band's end and
     * the nodes are hats (1 nm and wider), the first at or beyond lambda_max, whose hat still covers the band's last
     * part (HatFilteredSpectrum: the hats of the grid sum to 1 on the band).
     */
    private int lastNode(double to, double spacing) {
        if (spacing >= 1 && to >= lambdaMaxNm - 1e-9) {
            return (int) Math.ceil((lambdaMaxNm - lambdaMinNm) / spacing - 1e-9);
        }
        return (int) Math.floor((to - lambdaMinNm) / spacing + 1e-9);
    }

    /**
     * Below 1 nm the rule is the trapezoid's on a grid that meets both ends of the band: the nodes at the ends weigh
     * half (hats, 1 nm and wider, take their ends from the table).
     */
    private double endWeight(double lambdaNm, double spacing) {
        if (spacing >= 1) {
            return 1;
        }
        return lambdaNm <= lambdaMinNm + 1e-6 || lambdaNm >= lambdaMaxNm - 1e-6 ? 0.5 : 1;
    }

    /** The lobe's weight W_c(k w) at lambda. */
    private static double weight(Weight lobe, double w, double lambdaNm) {
        return lobe.at(2 * Math.PI / (lambdaNm * 1e-3) * w, lambdaNm);
    }

    /**
     * The node spacing for a lobe: the width in nm of its passage (its standard deviation, widened by the footprint's
     * Gaussian, over the speed lambda -&gt; mu per nm) over the nodes per sigma, on the hat levels or below 1 nm.
     */
    private double spacingNm(double cx, double cy, Shape shape, double fromNm) {
        double lobeVariance = 0.5 * square(fromNm * 1e-3 * sigmaFPerUm);
        // under a disc the rims are the passage's edges, as wide as the lobe and the box across them (a disc without
        // rims: as wide as its Gaussian); 0 otherwise
        double widthNm = Double.POSITIVE_INFINITY;
        if (cx != 0) {
            widthNm = Math.min(widthNm, Math.sqrt(lobeVariance + shape.gaussian.xx() + shape.passageU) / Math.abs(cx)
                    * 1e3);
        }
        if (cy != 0) {
            widthNm = Math.min(widthNm, Math.sqrt(lobeVariance + shape.gaussian.yy() + shape.passageV) / Math.abs(cy)
                    * 1e3);
        }
        // never wider than the band: a band narrower than the nodes' spacing would be seen through one node
        double bandNm = lambdaMaxNm - lambdaMinNm;
        double target = Math.min(Math.min(widthNm / quadrature.nodesPerSigma(), quadrature.maxStepNm()), bandNm);
        return spacingOnLevels(target);
    }

    /** A target spacing rounded down onto the hat levels (1, 2, 4, 8, 16 nm), or below 1 nm a part of the band. */
    private double spacingOnLevels(double target) {
        double bandNm = lambdaMaxNm - lambdaMinNm;
        if (target >= 1) {
            return Math.pow(2, Math.floor(Math.log(target) / Math.log(2) + 1e-12));
        }
        // below 1 nm: a whole number of steps across the band, so that the nodes meet both its ends
        return bandNm / Math.ceil(bandNm / Math.max(target, 1e-3) - 1e-9);
    }

    /** The lobe at wavelength lambda averaged over the footprint. */
    private double averaged(double lambdaUm, double cx, double cy, double u, double v, Shape shape) {
        double sigmaUv = lambdaUm * sigmaFPerUm;
        double muU = lambdaUm * cx;
        double muV = lambdaUm * cy;
        if (!shape.hasBox()) {
            return LobeGeometry.averagedLobe(sigmaUv, muU, muV, u, v, 0, 0, shape.gaussian, fastErf);
        }
        double sum = 0;
        for (int k = 0; k < shape.shiftWeight.length; k++) {
            sum += shape.shiftWeight[k] * LobeGeometry.averagedLobe(sigmaUv, muU, muV, u + shape.shiftU[k],
                    v + shape.shiftV[k], shape.hx, shape.hy, shape.gaussian, fastErf);
        }
        return sum;
    }

    /** |P|^2 at one wavelength averaged over the footprint: sum over lobes of W_c A_c (monochromatic maps). */
    public double power(double u, double v, double w, double lambdaNm, Footprint footprint) {
        return power(u, v, w, lambdaNm, footprint, null);
    }

    /** As above under a disc light (null: none), relative to the gain at the light's centre. */
    public double power(double u, double v, double w, double lambdaNm, Footprint footprint, DiscFootprint disc) {
        double lambdaUm = lambdaNm * 1e-3;
        Shape shape = new Shape(footprint, quadrature, 0.5 * square(lambdaUm * sigmaFPerUm), disc);
        int step = lobes.hasPairs() ? 1 : 2;
        double a = 2 * Math.PI / lambdaUm * w;
        double[] at = new double[2];
        double sum = 0;
        for (int tx = first((u - shape.reachU) * extentXUm / lambdaUm, step);
             tx <= Math.ceil(2 * (u + shape.reachU) * extentXUm / lambdaUm); tx += step) {
            for (int ty = first((v - shape.reachV) * extentYUm / lambdaUm, step);
                 ty <= Math.ceil(2 * (v + shape.reachV) * extentYUm / lambdaUm); ty += step) {
                Weight lobe = weightOf(tx, ty);
                if (lobe == null) {
                    continue;
                }
                double cx = 0.5 * tx / extentXUm;
                double cy = 0.5 * ty / extentYUm;
                if (disc != null) {
                    disc.average(lambdaUm * sigmaFPerUm, lambdaUm * cx, lambdaUm * cy, shape.hx, shape.hy,
                            shape.gaussian, fastErf, at);
                    sum += lobe.at(2 * Math.PI / lambdaUm * at[1], lambdaNm) * at[0];
                    continue;
                }
                sum += lobe.at(a, lambdaNm) * averaged(lambdaUm, cx, cy, u, v, shape);
            }
        }
        return sum;
    }

    private static double square(double x) {
        return x * x;
    }
}
