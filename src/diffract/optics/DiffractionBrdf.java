package diffract.optics;

import diffract.colour.SpectralIntegrator;
import diffract.colour.Xyz;

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

    public DiffractionBrdf(PatchSpectrum spectrum, WavelengthSampling sampling, double refractiveIndex) {
        this.spectrum = spectrum;
        this.sampling = sampling;
        this.refractiveIndex = refractiveIndex;
    }

    /**
     * Builds the variant the settings name. {@code terms} (the precomputed float32 Taylor terms) are needed for
     * FLSS, NMM and PQ; {@code meanSubtracted} for the reference.
     */
    public static DiffractionBrdf create(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        if (settings.variant() == Variant.REFERENCE) {
            PatchSpectrum exact = new ExactSpectrum(meanSubtracted, settings.coherenceWindow());
            return new DiffractionBrdf(exact, WavelengthSampling.uniform(settings.spectral().lambdaMinNm(),
                    settings.spectral().lambdaMaxNm(), SpectralSettings.REFERENCE_STEP_NM),
                    settings.illumination().refractiveIndex());
        }
        if (settings.variant() == Variant.BAKED) {
            throw new InvalidSettingException(Quantity.VARIANT, BAKED_IS_GPU_ONLY);
        }
        return withSampling(settings, taylorSpectrum(settings, terms, settings.taylor().highestOrder()));
    }

    /**
     * FLSS, NMM or PQ summed around the nearest phase centre ({@link PhaseCentredSpectrum}) instead of
     * around 0: the same window, lookup and wavelengths, every order of every centre ({@code settings.taylor().highestOrder()}
     * does not apply; the centres fix their own orders).
     */
    public static DiffractionBrdf createPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        if (settings.variant() == Variant.REFERENCE) {
            throw new IllegalArgumentException("the reference needs no Taylor expansion");
        }
        int orders = terms.centres().highestOrder();
        return withSampling(settings, new PhaseCentredSpectrum(terms, t -> taylorSpectrum(settings, t, orders)));
    }

    /** The variant's Taylor-series spectrum over float32 terms: Gaussian window (FLSS, NMM) or sinc (PQ). */
    private static PatchSpectrum taylorSpectrum(BrdfSettings settings, TaylorTerms terms, int highestOrder) {
        CoherenceWindow window = settings.coherenceWindow();
        WindowRadii radii = settings.windowRadii(terms.cols() * terms.pixelSizeXUm(),
                terms.rows() * terms.pixelSizeYUm());
        double tolerance = settings.taylor().tolerance();
        switch (settings.variant()) {
            case FLSS:
            case NMM:
                return new TaylorGaussianSpectrum(terms, highestOrder, radii, tolerance, window);
            case PQ: {
                double extentX = terms.cols() * terms.pixelSizeXUm();
                double extentY = terms.rows() * terms.pixelSizeYUm();
                return new TaylorSincSpectrum(terms, highestOrder, radii, tolerance,
                        settings.window().replicas(window, extentX), settings.window().replicas(window, extentY));
            }
            case BAKED:
                throw new InvalidSettingException(Quantity.VARIANT, BAKED_IS_GPU_ONLY);
            default:
                throw new IllegalStateException("unhandled variant " + settings.variant());
        }
    }

    /** The variant's wavelengths: NMM's nodes, or the uniform grid of FLSS and PQ. */
    private static DiffractionBrdf withSampling(BrdfSettings settings, PatchSpectrum s) {
        SpectralSettings spectral = settings.spectral();
        double min = spectral.lambdaMinNm();
        double max = spectral.lambdaMaxNm();
        WavelengthSampling sampling = settings.variant() == Variant.NMM
                ? WavelengthSampling.nmm(min, max, spectral.lambdaStepNm(), s.extentXUm(), s.extentYUm(), NMM_MAX_NODES)
                : WavelengthSampling.uniform(min, max, spectral.lambdaStepNm());
        return new DiffractionBrdf(s, sampling, settings.illumination().refractiveIndex());
    }
    /** One line for the CLI and the API when the baked table is asked of the CPU. */
    public static final String BAKED_IS_GPU_ONLY = "the baked variant is a table on the GPU; "
            + "on the CPU use flss, which it tabulates";

    /** NMM's node budget per fragment: beyond it, uniform steps are cheaper anyway. */
    public static final int NMM_MAX_NODES = 1024;

    /** The relative BRDF at one wavelength (grey BRDF maps, grating-equation tests). */
    public double relative(Direction wi, Direction wr, double lambdaNm) {
        double gain = GainFactor.gainTimesShadowing(wi, wr, refractiveIndex);
        if (gain == 0) {
            return 0;
        }
        double u = -wi.x() - wr.x();
        double v = -wi.y() - wr.y();
        double w = -wi.z() - wr.z();
        return gain * spectrum.power(u, v, w, lambdaNm * 1e-3);
    }

    /** CIE XYZ of the light reflected towards omega_r, relative to D65 white (Y = 1 for a flat mirror at normal incidence). */
    public Xyz xyz(Direction wi, Direction wr) {
        double gain = GainFactor.gainTimesShadowing(wi, wr, refractiveIndex);
        if (gain == 0) {
            return new Xyz(0, 0, 0);
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

    public PatchSpectrum spectrum() {
        return spectrum;
    }
}
