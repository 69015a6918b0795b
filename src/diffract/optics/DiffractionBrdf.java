package diffract.optics;

import diffract.colour.SpectralIntegrator;
import diffract.colour.Xyz;
import diffract.util.UserInputException;

/**
 * The relative diffraction BRDF of a patch (004): monochromatic, rho_lambda = C(omega_i, omega_r) S |P|^2
 * (eq. {@code cpterm} with Stam's shadowing S), and integrated to colour,
 * XYZ = C S sum_j |P(lambda_j)|^2 weights_j (eq. {@code finalexpression}; the weights are CMF x D65 times the
 * quadrature weights, normalised so a flat mirror seen at normal incidence is exactly D65 white, Y = 1).
 * Immutable and thread-safe.
 */
public final class DiffractionBrdf {
    private final PatchSpectrum spectrum;
    private final WavelengthSampling sampling;
    private final double refractiveIndex;
    private final FresnelModel fresnel;
    private final OpticsOptions options;
    /** The filtered reference (REFERENCE whose options filter), else null. */
    private final FilteredReference filteredReference;
    /** The lobes method (LOBES), else null. */
    private final LobeSpectrum lobes;

    /** With the {@link FresnelModel#PHYSICAL} gain factor. */
    public DiffractionBrdf(PatchSpectrum spectrum, WavelengthSampling sampling, double refractiveIndex) {
        this(spectrum, sampling, refractiveIndex, FresnelModel.PHYSICAL);
    }

    public DiffractionBrdf(PatchSpectrum spectrum, WavelengthSampling sampling, double refractiveIndex,
                           FresnelModel fresnel) {
        this(spectrum, sampling, refractiveIndex, OpticsOptions.POINT_SAMPLED.withFresnel(fresnel), null, null);
    }

    private DiffractionBrdf(PatchSpectrum spectrum, WavelengthSampling sampling, double refractiveIndex,
                            OpticsOptions options, FilteredReference filteredReference, LobeSpectrum lobes) {
        this.spectrum = spectrum;
        this.sampling = sampling;
        this.refractiveIndex = refractiveIndex;
        this.fresnel = options.fresnel();
        this.options = options;
        this.filteredReference = filteredReference;
        this.lobes = lobes;
    }

    /**
     * Builds the variant the settings name, point-sampled ({@link OpticsOptions#POINT_SAMPLED}). {@code terms} (the
     * precomputed float32 Taylor terms) are needed for FLSS, NMM, PQ and LOBES; {@code meanSubtracted} for the
     * reference.
     */
    public static DiffractionBrdf create(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        return create(settings, meanSubtracted, terms, OpticsOptions.POINT_SAMPLED);
    }

    /**
     * As above with the optics options: Fresnel model, light size, pixel filter. The reference then integrates the
     * defined pixel values ({@link FilteredReference}) whenever the options filter (a box or a light); flss, nmm and
     * pq refuse a light (they point-sample it) and point-sample pixels.
     */
    public static DiffractionBrdf create(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms,
                                         OpticsOptions options) {
        if (settings.variant() == Variant.REFERENCE) {
            ExactSpectrum exact = new ExactSpectrum(meanSubtracted, settings.coherenceWindow());
            FilteredReference filtered = options.filters() ? new FilteredReference(exact, settings.coherenceWindow(),
                    settings.lambdaMinNm(), settings.lambdaMaxNm(), settings.refractiveIndex(), options.fresnel())
                    : null;
            return new DiffractionBrdf(exact, WavelengthSampling.uniform(settings.lambdaMinNm(),
                    settings.lambdaMaxNm(), BrdfSettings.REFERENCE_STEP_NM), settings.refractiveIndex(), options,
                    filtered, null);
        }
        if (settings.variant() == Variant.BAKED) {
            throw new UserInputException(BAKED_IS_GPU_ONLY);
        }
        if (settings.variant() == Variant.LOBES) {
            return withLobes(settings, options, LobeSpectrum.ofTerms(terms, settings.highestOrder(),
                    settings.coherenceWindow(), settings.lambdaMinNm(), settings.lambdaMaxNm(), options.lobes()));
        }
        requirePointLight(settings, options);
        return withSampling(settings, options, taylorSpectrum(settings, terms, settings.highestOrder()));
    }

    /**
     * FLSS, NMM, PQ or LOBES summed around the nearest phase centre (issue #6, {@link PhaseCentredSpectrum}) instead
     * of around 0: the same window, lookup and wavelengths, every order of every centre ({@code
     * settings.highestOrder()} does not apply; the centres fix their own orders).
     */
    public static DiffractionBrdf createPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        return createPhaseCentred(settings, terms, OpticsOptions.POINT_SAMPLED);
    }

    /** As above with the optics options. */
    public static DiffractionBrdf createPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms,
                                                     OpticsOptions options) {
        if (settings.variant() == Variant.REFERENCE) {
            throw new IllegalArgumentException("the reference needs no Taylor expansion");
        }
        if (settings.variant() == Variant.LOBES) {
            return withLobes(settings, options, LobeSpectrum.ofTerms(terms, settings.coherenceWindow(),
                    settings.lambdaMinNm(), settings.lambdaMaxNm(), options.lobes()));
        }
        requirePointLight(settings, options);
        int orders = terms.centres().highestOrder();
        return withSampling(settings, options, new PhaseCentredSpectrum(terms, t -> taylorSpectrum(settings, t, orders)));
    }

    private static DiffractionBrdf withLobes(BrdfSettings settings, OpticsOptions options, LobeSpectrum lobes) {
        PatchSpectrum point = new PatchSpectrum() {
            @Override
            public double power(double u, double v, double w, double lambdaUm) {
                return lobes.power(u, v, w, lambdaUm * 1e3, Footprint.POINT);
            }

            @Override
            public double extentXUm() {
                return lobes.extentXUm();
            }

            @Override
            public double extentYUm() {
                return lobes.extentYUm();
            }
        };
        return new DiffractionBrdf(point, null, settings.refractiveIndex(), options, null, lobes);
    }

    /** One line for a light of finite size asked of a point-sampling variant. */
    static void requirePointLight(BrdfSettings settings, OpticsOptions options) {
        if (!options.light().isPoint()) {
            throw new UserInputException(settings.variant().cliName() + " samples the light at its centre only: "
                    + "for a light of " + options.light().angularDiameterDeg() + " degrees use --variant lobes or "
                    + "reference (or --light-size-deg 0)");
        }
    }

    /** The variant's Taylor-series spectrum over float32 terms: Gaussian window (FLSS, NMM) or sinc (PQ). */
    private static PatchSpectrum taylorSpectrum(BrdfSettings settings, TaylorTerms terms, int highestOrder) {
        CoherenceWindow window = settings.coherenceWindow();
        WindowRadii radii = settings.windowRadii(terms.cols() * terms.pixelSizeXUm(),
                terms.rows() * terms.pixelSizeYUm());
        double tolerance = settings.taylorTolerance();
        switch (settings.variant()) {
            case FLSS:
            case NMM:
                return new TaylorGaussianSpectrum(terms, highestOrder, radii, tolerance, window);
            case PQ: {
                double extentX = terms.cols() * terms.pixelSizeXUm();
                double extentY = terms.rows() * terms.pixelSizeYUm();
                int rx = settings.pqReplicas() > 0 ? settings.pqReplicas()
                        : TaylorSincSpectrum.replicasForCoherence(window, extentX);
                int ry = settings.pqReplicas() > 0 ? settings.pqReplicas()
                        : TaylorSincSpectrum.replicasForCoherence(window, extentY);
                return new TaylorSincSpectrum(terms, highestOrder, radii, tolerance, rx, ry);
            }
            case BAKED:
                throw new UserInputException(BAKED_IS_GPU_ONLY);
            default:
                throw new IllegalStateException("unhandled variant " + settings.variant());
        }
    }

    /** The variant's wavelengths: NMM's nodes, or the uniform grid of FLSS and PQ. */
    private static DiffractionBrdf withSampling(BrdfSettings settings, OpticsOptions options, PatchSpectrum s) {
        double min = settings.lambdaMinNm();
        double max = settings.lambdaMaxNm();
        WavelengthSampling sampling = settings.variant() == Variant.NMM
                ? WavelengthSampling.nmm(min, max, settings.lambdaStepNm(), s.extentXUm(), s.extentYUm(), NMM_MAX_NODES)
                : WavelengthSampling.uniform(min, max, settings.lambdaStepNm());
        return new DiffractionBrdf(s, sampling, settings.refractiveIndex(), options, null, null);
    }
    /** One line for the CLI and the API when the baked table is asked of the CPU. */
    public static final String BAKED_IS_GPU_ONLY = "the baked variant is a GPU table (--engine gpu); "
            + "on the CPU use flss, which it tabulates";

    /** NMM's node budget per fragment: beyond it, uniform steps are cheaper anyway. */
    public static final int NMM_MAX_NODES = 1024;

    /** The relative BRDF at one wavelength (grey BRDF maps, grating-equation tests). */
    public double relative(Direction wi, Direction wr, double lambdaNm) {
        double gain = GainFactor.gainTimesShadowing(wi, wr, refractiveIndex, fresnel);
        if (gain == 0) {
            return 0;
        }
        double u = -wi.x() - wr.x();
        double v = -wi.y() - wr.y();
        double w = -wi.z() - wr.z();
        return gain * spectrum.power(u, v, w, lambdaNm * 1e-3);
    }

    /**
     * CIE XYZ of the light reflected towards omega_r, relative to D65 white (Y = 1 for a flat mirror at normal
     * incidence): at the direction itself (no pixel), averaged over the options' light for the reference and lobes.
     */
    public Xyz xyz(Direction wi, Direction wr) {
        if (filteredReference != null) {
            double[] v = filteredReference.at(wi, wr, Footprint.POINT.plus(options.light().uvCovariance(wi)));
            return new Xyz(v[0], v[1], v[2]);
        }
        double gain = GainFactor.gainTimesShadowing(wi, wr, refractiveIndex, fresnel);
        if (gain == 0) {
            return new Xyz(0, 0, 0);
        }
        if (lobes != null) {
            double[] v = lobes.xyz(-wi.x() - wr.x(), -wi.y() - wr.y(), -wi.z() - wr.z(),
                    Footprint.POINT.plus(options.light().uvCovariance(wi)));
            return new Xyz(gain * v[0], gain * v[1], gain * v[2]);
        }
        double u = -wi.x() - wr.x();
        double v = -wi.y() - wr.y();
        double w = -wi.z() - wr.z();
        WavelengthSampling.Quadrature q = sampling.quadratureFor(u, v);
        double[] lambdas = q.lambdasNm();
        double[] power = new double[lambdas.length];
        for (int j = 0; j < lambdas.length; j++) {
            power[j] = spectrum.power(u, v, w, lambdas[j] * 1e-3);
        }
        Xyz sum = SpectralIntegrator.weightedSum(q.xyzWeights(), power);
        return new Xyz(gain * sum.x(), gain * sum.y(), gain * sum.z());
    }

    /**
     * Pixel (column, row) of an S x S BRDF map ({@link BrdfMap}'s convention): with {@link PixelFilter#BOX} the
     * reference and the lobes method average over the pixel's square; otherwise the pixel's centre direction
     * ({@link #xyz}). Black outside the unit disk.
     */
    public Xyz mapPixel(Direction wi, int column, int row, int size) {
        double x = BrdfMap.xOf(column, size);
        double y = BrdfMap.yOf(row, size);
        if (x * x + y * y >= 1.0) {
            return new Xyz(0, 0, 0);
        }
        Direction wr = Direction.fromProjected(x, y);
        if (options.pixelFilter() != PixelFilter.BOX || (filteredReference == null && lobes == null)) {
            return xyz(wi, wr);
        }
        Covariance2 light = options.light().uvCovariance(wi);
        if (filteredReference != null) {
            return filteredReference.mapPixel(wi, light, column, row, size);
        }
        double gain = GainFactor.gainTimesShadowing(wi, wr, refractiveIndex, fresnel);
        if (gain == 0) {
            return new Xyz(0, 0, 0);
        }
        double[] v = lobes.xyz(-wi.x() - x, -wi.y() - y, -wi.z() - wr.z(), Footprint.mapPixel(size).plus(light));
        return new Xyz(gain * v[0], gain * v[1], gain * v[2]);
    }

    public OpticsOptions options() {
        return options;
    }

    /** The lobes method of a LOBES BRDF, else null. */
    public LobeSpectrum lobes() {
        return lobes;
    }

    public PatchSpectrum spectrum() {
        return spectrum;
    }
}
