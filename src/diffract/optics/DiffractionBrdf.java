package diffract.optics;

import diffract.colour.SpectralIntegrator;
import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.DiscFootprint;
import diffract.optics.illumination.Footprint;
import diffract.optics.illumination.GainFactor;
import diffract.optics.illumination.IlluminationSettings;
import diffract.optics.illumination.LightSource;
import diffract.optics.numerics.Covariance2;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.OrderWeights;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.Quantity;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.settings.WavelengthSampling;
import diffract.optics.spectra.ExactSpectrum;
import diffract.optics.spectra.PatchSpectrum;
import diffract.optics.spectra.PhaseCentredSpectrum;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.TaylorGaussianSpectrum;
import diffract.optics.spectra.TaylorSincSpectrum;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.LocalWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.windows.WindowRadii;
import diffract.util.DiskCache;
import diffract.util.Reporter;

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
    private final IlluminationSettings illumination;
    /** The filtered reference (REFERENCE whose illumination filters), else null. */
    private final FilteredReference filteredReference;
    /** The reference under a disc light (null for a Gaussian or point light). */
    private final DiscLightAverage discLight;
    /** The lobes method (LOBES), else null. */
    private final LobeSpectrum lobes;
    /** The rigorous method, else null. */
    private final RigorousBrdf rigorous;
    /** The lobes method's orders from Maxwell's equations ({@link OrderWeights#RIGOROUS}), else null. */
    private final LobeOrders lobeOrders;

    /** The lobes' table of rigorous orders of one patch, solved (or loaded) at its first use. */
    private static final class LobeOrders {
        private final HeightField field;
        private final BrdfSettings settings;
        private OrderCorrection table;

        LobeOrders(HeightField field, BrdfSettings settings) {
            this.field = field;
            this.settings = settings;
        }

        synchronized OrderCorrection get(Reporter reporter) {
            if (table == null) {
                table = OrderCorrection.of(field, settings, DiskCache.user(), reporter);
            }
            return table;
        }
    }

    /**
     * A spectrum integrated over {@code sampling} under a point light, each direction point-sampled, with the
     * physical Fresnel factor (tests and measurements that build their own spectrum).
     */
    public DiffractionBrdf(PatchSpectrum spectrum, WavelengthSampling sampling, double refractiveIndex) {
        this(spectrum, sampling, IlluminationSettings.ofCoherenceLength(CoherenceWindow.COHERENCE_LENGTH_UM,
                refractiveIndex), null, null);
    }

    /** As above with the gain factor's Fresnel model. */
    public DiffractionBrdf(PatchSpectrum spectrum, WavelengthSampling sampling, double refractiveIndex,
                           GainModel gain) {
        this(spectrum, sampling, IlluminationSettings.ofCoherenceLength(CoherenceWindow.COHERENCE_LENGTH_UM,
                refractiveIndex).withGain(gain), null, null);
    }

    private DiffractionBrdf(PatchSpectrum spectrum, WavelengthSampling sampling, IlluminationSettings illumination,
                            FilteredReference filteredReference, LobeSpectrum lobes) {
        this(spectrum, sampling, illumination, filteredReference, lobes, null, null);
    }

    private DiffractionBrdf(PatchSpectrum spectrum, WavelengthSampling sampling, IlluminationSettings illumination,
                            FilteredReference filteredReference, LobeSpectrum lobes, RigorousBrdf rigorous,
                            LobeOrders lobeOrders) {
        this.spectrum = spectrum;
        this.sampling = sampling;
        this.illumination = illumination;
        this.filteredReference = filteredReference;
        this.lobes = lobes;
        this.rigorous = rigorous;
        this.lobeOrders = lobeOrders;
        this.discLight = filteredReference != null && illumination.light().isDisc()
                ? new DiscLightAverage(filteredReference, illumination.light()) : null;
    }

    /** The reference's disc integral (the reference under a disc light), else empty. */
    public java.util.Optional<DiscLightAverage> discLight() {
        return java.util.Optional.ofNullable(discLight);
    }

    /**
     * Builds the variant the settings name. {@code terms} (the precomputed float32 Taylor terms) are needed for
     * FLSS, NMM, PQ and LOBES; {@code meanSubtracted} for the reference. The illumination's light and pixel filter
     * are honoured by the reference (which then integrates the defined pixel values, {@link FilteredReference})
     * and the lobes method; flss, nmm and pq point-sample pixels and refuse an extended light.
     */
    public static DiffractionBrdf create(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        requireNotLocal(settings);
        LightPolicy.of(settings).requireAccepted();
        return settings.variant().cpuBrdf(settings, meanSubtracted, terms);
    }

    /** The exact reference (called by its method class): exp(i k w h) transformed at 1 nm, filtered where asked. */
    static DiffractionBrdf reference(BrdfSettings settings, HeightField meanSubtracted) {
        IlluminationSettings illumination = settings.illumination();
        ExactSpectrum exact = new ExactSpectrum(meanSubtracted, settings.coherenceWindow());
        SpectralSettings spectral = settings.spectral();
        FilteredReference filtered = illumination.filters() ? new FilteredReference(exact,
                settings.coherenceWindow(), spectral, illumination.refractiveIndex(), illumination.gain())
                : null;
        return new DiffractionBrdf(exact, WavelengthSampling.uniform(spectral.lambdaMinNm(),
                spectral.lambdaMaxNm(), SpectralSettings.REFERENCE_STEP_NM, spectral.normalisation()),
                illumination, filtered, null);
    }

    /**
     * The rigorous method (called by its method class): the patch's orders from Maxwell's equations
     * ({@link RigorousOrders}) drawn as the reference draws its lobes, kept in the user's disk cache.
     */
    static DiffractionBrdf rigorous(BrdfSettings settings, HeightField meanSubtracted) {
        RigorousPatch patch = RigorousPatch.of(meanSubtracted);
        patch.refusal(settings.rigorous().resolution(), settings.spectral().lambdaMinNm() * 1e-3).ifPresent(why -> {
            throw new InvalidSettingException(Quantity.VARIANT, why);
        });
        return new DiffractionBrdf(null, null, settings.illumination(), null, null,
                new RigorousBrdf(patch, settings, DiskCache.user()), null);
    }

    /**
     * Readies the BRDF for maps lit from {@code wi}, reporting progress: the rigorous method solves its orders for
     * that direction here (minutes); every other method has nothing to do.
     */
    public void prepare(Direction wi, Reporter reporter) {
        if (rigorous != null) {
            rigorous.prepare(wi, reporter);
        }
        if (lobeOrders != null) {
            lobeOrders.get(reporter);
        }
    }

    /**
     * This BRDF with the settings' orders: where they are the rigorous ones and this is the lobes method, its lobes
     * take the table of {@code meanSubtracted}'s rigorous orders ({@link OrderCorrection}); otherwise this BRDF.
     */
    public DiffractionBrdf withOrdersOf(HeightField meanSubtracted, BrdfSettings settings) {
        if (lobes == null || settings.rigorous().orders() != OrderWeights.RIGOROUS) {
            return this;
        }
        return new DiffractionBrdf(spectrum, sampling, illumination, filteredReference, lobes, null,
                new LobeOrders(meanSubtracted, settings));
    }

    /** The lobes for light from {@code wi}: with the rigorous orders on them where asked. */
    private LobeSpectrum lobesFor(Direction wi) {
        return lobeOrders == null ? lobes : lobes.withOrders(lobeOrders.get(Reporter.SILENT), wi);
    }

    /**
     * FLSS, NMM, PQ or LOBES summed around the nearest phase centre ({@link PhaseCentredSpectrum}) instead of
     * around 0: the same window, lookup and wavelengths, every order of every centre
     * ({@code settings.taylor().highestOrder()} does not apply; the centres fix their own orders).
     */
    public static DiffractionBrdf createPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        requireNotLocal(settings);
        LightPolicy.of(settings).requireAccepted();
        return settings.variant().cpuBrdfPhaseCentred(settings, terms);
    }

    /**
     * FLSS or NMM with the window under one surface point, averaged over the pixel's footprint there
     * ({@link LocalWindow}): the CPU's exact counterpart of a mesh's fragment under {@link WindowPlacement#LOCAL}.
     */
    public static DiffractionBrdf createLocal(BrdfSettings settings, TaylorTerms terms, LocalWindow local) {
        if (!settings.variant().drawsLocalWindow()) {
            throw new InvalidSettingException(Quantity.WINDOW_PLACEMENT, LOCAL_NEEDS_FLSS_OR_NMM);
        }
        LightPolicy.of(settings).requireAccepted();
        TaylorGaussianSpectrum spectrum = new TaylorGaussianSpectrum(terms, settings.taylor().highestOrder(),
                settings.windowRadii(terms.cols() * terms.pixelSizeXUm(), terms.rows() * terms.pixelSizeYUm()),
                settings.taylor().tolerance(), settings.coherenceWindow());
        return settings.variant().cpuBrdfLocal(settings, spectrum.under(local));
    }

    /** One line when the local window is asked of something without a surface point. */
    public static final String LOCAL_NEEDS_A_SURFACE = "the local window follows the surface point a pixel sees, and a"
            + " BRDF map has none: use averaged (what local converges to where a pixel covers the scan) or fixed (the"
            + " window at the scan's origin)";

    /** One line when the local window is asked of a method that does not sum the window's texels itself. */
    public static final String LOCAL_NEEDS_FLSS_OR_NMM = "the local window is drawn by flss and nmm, which sum the"
            + " window's texels per fragment; the other methods draw the window averaged over its position";

    private static void requireNotLocal(BrdfSettings settings) {
        if (settings.window().placement() == WindowPlacement.LOCAL) {
            throw new InvalidSettingException(Quantity.WINDOW_PLACEMENT, LOCAL_NEEDS_A_SURFACE);
        }
    }

    /** The lobes method (called by its method class) over its spectrum, its footprints and lights its own. */
    static DiffractionBrdf withLobes(BrdfSettings settings, LobeSpectrum lobes) {
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
        return new DiffractionBrdf(point, null, settings.illumination(), null, lobes);
    }

    /** The Taylor series over float32 terms under the Gaussian window of FLSS and NMM (003 eq. 1.10). */
    static PatchSpectrum gaussianWindowSpectrum(BrdfSettings settings, TaylorTerms terms, int highestOrder) {
        return new TaylorGaussianSpectrum(terms, highestOrder, radii(settings, terms), settings.taylor().tolerance(),
                settings.coherenceWindow());
    }

    /** The Taylor series over float32 terms, periodically replicated and sinc-interpolated (PQ, 003 sec. 1.5.3). */
    static PatchSpectrum sincSpectrum(BrdfSettings settings, TaylorTerms terms, int highestOrder) {
        CoherenceWindow window = settings.coherenceWindow();
        double extentX = terms.cols() * terms.pixelSizeXUm();
        double extentY = terms.rows() * terms.pixelSizeYUm();
        return new TaylorSincSpectrum(terms, highestOrder, radii(settings, terms), settings.taylor().tolerance(),
                settings.window().replicas(window, extentX), settings.window().replicas(window, extentY),
                window.placement());
    }

    private static WindowRadii radii(BrdfSettings settings, TaylorTerms terms) {
        return settings.windowRadii(terms.cols() * terms.pixelSizeXUm(), terms.rows() * terms.pixelSizeYUm());
    }

    /** {@code s} at the uniform wavelength grid of the settings (FLSS, PQ). */
    static DiffractionBrdf uniformlySampled(BrdfSettings settings, PatchSpectrum s) {
        SpectralSettings spectral = settings.spectral();
        return new DiffractionBrdf(s, WavelengthSampling.uniform(spectral.lambdaMinNm(), spectral.lambdaMaxNm(),
                spectral.lambdaStepNm(), spectral.normalisation()), settings.illumination(), null, null);
    }

    /** {@code s} at NMM's nodes, the wavelengths that land on texel centres (003 sec. 1.5.2). */
    static DiffractionBrdf sampledOnTexelCentres(BrdfSettings settings, PatchSpectrum s) {
        SpectralSettings spectral = settings.spectral();
        return new DiffractionBrdf(s, WavelengthSampling.nmm(spectral.lambdaMinNm(), spectral.lambdaMaxNm(),
                spectral.lambdaStepNm(), s.extentXUm(), s.extentYUm(), NMM_MAX_NODES, spectral.normalisation()),
                settings.illumination(), null, null);
    }

    /** One line for the CLI and the API when the baked table is asked of the CPU. */
    public static final String BAKED_IS_GPU_ONLY = "the baked variant is a table on the GPU; "
            + "on the CPU use flss, which it tabulates";

    /** NMM's node budget per fragment: beyond it, uniform steps are cheaper anyway. */
    public static final int NMM_MAX_NODES = 1024;

    /** The relative BRDF at one wavelength (grey BRDF maps, grating-equation tests). */
    public double relative(Direction wi, Direction wr, double lambdaNm) {
        if (rigorous != null) {
            return rigorous.relative(wi, wr, lambdaNm);
        }
        if (lobeOrders != null) {
            double gain = GainFactor.gainTimesShadowing(wi, wr, illumination.refractiveIndex(), illumination.gain());
            return gain == 0 ? 0 : gain * lobesFor(wi).power(-wi.x() - wr.x(), -wi.y() - wr.y(), -wi.z() - wr.z(),
                    lambdaNm, Footprint.POINT);
        }
        double gain = GainFactor.gainTimesShadowing(wi, wr, illumination.refractiveIndex(), illumination.gain());
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
     * incidence): at the direction itself (no pixel), averaged over the illumination's light for the reference and lobes.
     */
    public Xyz xyz(Direction wi, Direction wr) {
        if (rigorous != null) {
            return rigorous.xyz(wi, wr);
        }
        if (discLight != null) {
            return discLight.at(wi, wr);
        }
        if (filteredReference != null) {
            double[] v = filteredReference.at(wi, wr, Footprint.POINT.plus(illumination.light().uvCovariance(wi)));
            return new Xyz(v[0], v[1], v[2]);
        }
        double gain = GainFactor.gainTimesShadowing(wi, wr, illumination.refractiveIndex(), illumination.gain());
        if (gain == 0) {
            return new Xyz(0, 0, 0);
        }
        if (lobes != null) {
            double[] v = lobesFor(wi).xyz(-wi.x() - wr.x(), -wi.y() - wr.y(), -wi.z() - wr.z(),
                    Footprint.POINT.plus(illumination.light().uvCovariance(wi)), discOf(wi, wr));
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
        if (rigorous != null) {
            return rigorous.mapPixel(wi, column, row, size);
        }
        Direction wr = Direction.fromProjected(x, y);
        if (illumination.pixelFilter() != PixelFilter.BOX || (filteredReference == null && lobes == null)) {
            return xyz(wi, wr);
        }
        if (discLight != null) {
            return discLight.mapPixel(wi, column, row, size);
        }
        Covariance2 light = illumination.light().uvCovariance(wi);
        if (filteredReference != null) {
            return filteredReference.mapPixel(wi, light, column, row, size);
        }
        double gain = GainFactor.gainTimesShadowing(wi, wr, illumination.refractiveIndex(), illumination.gain());
        if (gain == 0) {
            return new Xyz(0, 0, 0);
        }
        double[] v = lobesFor(wi).xyz(-wi.x() - x, -wi.y() - y, -wi.z() - wr.z(), Footprint.mapPixel(size).plus(light),
                discOf(wi, wr));
        return new Xyz(gain * v[0], gain * v[1], gain * v[2]);
    }

    /** The lobes method's view of a disc light from omega_r ({@link DiscFootprint}); null for a point or Gaussian. */
    private DiscFootprint discOf(Direction wi, Direction wr) {
        LightSource light = illumination.light();
        return light.isDisc() ? new DiscFootprint(light, wi, wr, illumination.refractiveIndex(), illumination.gain())
                : null;
    }

    /** The light, pixel filter and Fresnel model this BRDF evaluates with. */
    public IlluminationSettings illumination() {
        return illumination;
    }

    /** The lobes method of a LOBES BRDF, else null. */
    public LobeSpectrum lobes() {
        return lobes;
    }

    public PatchSpectrum spectrum() {
        return spectrum;
    }
}
