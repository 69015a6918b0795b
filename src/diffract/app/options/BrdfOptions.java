package diffract.app.options;

import diffract.colour.MirrorNormalisation;
import diffract.optics.BrdfSettings;
import diffract.optics.settings.GainModel;
import diffract.optics.illumination.IlluminationSettings;
import diffract.optics.settings.LightProfile;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.OrderWeights;
import diffract.optics.settings.Polarisation;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.rigorous.Resolution;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.patches.ScanTiling;
import diffract.optics.windows.WindowPlacement;
import diffract.util.UserInputException;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Option;

/**
 * The BRDF settings as options, the same on {@code brdfmap}, {@code view} and {@code render}, in the groups of
 * {@link BrdfSettings} (the help lists them under one heading each). Each option changes its setting only when
 * given: on top of the thesis' configuration, or of a scene file's material. The settings check the values; the
 * command line names the option of a refused value ({@link OptionNames}). A new group of settings is a new nested
 * group here, read in {@link #apply}.
 */
public final class BrdfOptions {
    @Option(names = "--variant", paramLabel = "V", converter = OptionTypes.VariantChoice.Converter.class,
            completionCandidates = OptionTypes.VariantChoice.Candidates.class)
    OptionTypes.VariantChoice variant;

    @Option(names = "--max-delta-e", paramLabel = "DE") public Double maxDeltaE;

    @ArgGroup(exclusive = false, validate = false, heading = "Taylor approximation:%n")
    Taylor taylor = new Taylor();

    @ArgGroup(exclusive = false, validate = false, heading = "Window between the DFT texels:%n")
    Window window = new Window();

    @ArgGroup(exclusive = false, validate = false, heading = "Spectral model:%n")
    Spectral spectral = new Spectral();

    @ArgGroup(exclusive = false, validate = false, heading = "Illumination:%n")
    Illumination illumination = new Illumination();

    @ArgGroup(exclusive = false, validate = false, heading = "Lobes method:%n")
    Lobes lobes = new Lobes();

    @ArgGroup(exclusive = false, validate = false, heading = "GPU tables:%n")
    GpuTables gpu = new GpuTables();

    @ArgGroup(exclusive = false, validate = false, heading = "Rigorous method:%n")
    Rigorous rigorous = new Rigorous();

    /** {@link diffract.optics.spectra.TaylorSettings}. */
    static final class Taylor {
        @Option(names = "--terms", paramLabel = "N") Integer highestOrder;

        @Option(names = "--taylor-tolerance", paramLabel = "EPS") Double tolerance;

        @Option(names = "--expansion", paramLabel = "E") TaylorExpansion expansion;
    }

    /** {@link diffract.optics.spectra.WindowSettings}. */
    static final class Window {
        @Option(names = "--window-radius", paramLabel = "R|auto", converter = OptionTypes.WindowRadius.Converter.class)
        OptionTypes.WindowRadius radius;

        @Option(names = "--pq-replicas", paramLabel = "R") Integer pqReplicas;

        @Option(names = "--window", paramLabel = "W", completionCandidates = OptionTypes.WindowPlacementNames.class)
        WindowPlacement placement;

        @Option(names = "--skin-um-per-texcoord", paramLabel = "U[,V]", split = ",", hideParamSyntax = true)
        double[] skinUmPerTexcoord;
    }

    /** {@link SpectralSettings}. */
    static final class Spectral {
        @Option(names = "--lambda-min", paramLabel = "NM") Double minNm;

        @Option(names = "--lambda-max", paramLabel = "NM") Double maxNm;

        @Option(names = "--lambda-step", paramLabel = "NM") Double stepNm;

        @Option(names = "--normalisation", paramLabel = "M",
                completionCandidates = OptionTypes.NormalisationNames.class)
        MirrorNormalisation normalisation;
    }

    /** {@link IlluminationSettings}. */
    static final class Illumination {
        @Option(names = "--coherence-length", paramLabel = "UM") Double coherenceLengthUm;

        @Option(names = "--refractive-index", paramLabel = "N[+Ki]", converter = OptionTypes.ComplexIndexConverter.class)
        diffract.optics.rigorous.ComplexIndex refractiveIndex;

        @Option(names = "--pixel-filter", paramLabel = "F", completionCandidates = OptionTypes.PixelFilterNames.class)
        PixelFilter pixelFilter;

        @Option(names = "--gain", paramLabel = "G", converter = OptionTypes.GainConverter.class,
                completionCandidates = OptionTypes.GainNames.class)
        GainModel gain;

        /** The former name of --gain (its "physical" is stam), kept for scripts that use it. */
        @Option(names = "--fresnel", paramLabel = "F", hidden = true, converter = OptionTypes.GainConverter.class)
        GainModel fresnel;

        @Option(names = "--light-size-deg", paramLabel = "DEG") Double lightSizeDeg;

        @Option(names = "--light-profile", paramLabel = "P", completionCandidates = OptionTypes.LightProfileNames.class)
        LightProfile lightProfile;
    }

    /** {@link diffract.optics.LobeQuadrature}. */
    static final class Lobes {
        @Option(names = "--lobe-quadrature", paramLabel = "K=V[,K=V]",
                converter = OptionTypes.LobeQuadratureChange.Converter.class)
        OptionTypes.LobeQuadratureChange quadrature;
    }

    /** {@link diffract.optics.GpuTableSettings}. */
    static final class GpuTables {
        @Option(names = "--texture-format", paramLabel = "F") TermFormat termFormat;

        @Option(names = "--baked-samples", paramLabel = "UV,W", converter = OptionTypes.BakedSamples.Converter.class)
        OptionTypes.BakedSamples bakedSamples;
    }

    /** {@link diffract.optics.rigorous.RigorousSettings}. */
    static final class Rigorous {
        @Option(names = "--harmonics", paramLabel = "M|auto", converter = OptionTypes.Harmonics.Converter.class)
        OptionTypes.Harmonics harmonics;

        @Option(names = "--layers", paramLabel = "L") Integer layers;

        @Option(names = "--no-layer-extrapolation") boolean noExtrapolation;

        @Option(names = "--polarisation", paramLabel = "P", completionCandidates = OptionTypes.PolarisationNames.class)
        Polarisation polarisation;

        @Option(names = "--orders", paramLabel = "W", completionCandidates = OptionTypes.OrderWeightsNames.class)
        OrderWeights orders;
    }

    public boolean auto() {
        return variant != null && variant.auto();
    }

    /** Whether N was given (it replaces a scene's tolerance-chosen N). */
    public boolean highestOrderGiven() {
        return taylor.highestOrder != null;
    }

    /** Checks the options that go together: an accuracy target exactly with auto. */
    public void validate() {
        if (auto() && maxDeltaE == null) {
            throw new UserInputException("--variant auto needs an accuracy target: --max-delta-e DE (mean CIEDE2000, e.g. 2)");
        }
        if (!auto() && maxDeltaE != null) {
            throw new UserInputException("--max-delta-e is the target of --variant auto; add --variant auto");
        }
        if (auto() && !(maxDeltaE > 0)) {
            throw new UserInputException("--max-delta-e must be > 0, got " + maxDeltaE);
        }
    }

    /**
     * {@code base} with every setting that was given on the command line. With auto the variant stays the
     * base's until {@link diffract.bench.AutoVariant} resolves it (it needs the patch).
     */
    public BrdfSettings apply(BrdfSettings base) {
        BrdfSettings.Builder b = base.toBuilder();
        if (variant != null && !variant.auto()) {
            b.variant(variant.variant());
        }
        if (taylor.highestOrder != null) {
            b.highestOrder(taylor.highestOrder);
        }
        if (taylor.tolerance != null) {
            b.taylorTolerance(taylor.tolerance);
        }
        if (taylor.expansion != null) {
            b.expansion(taylor.expansion);
        }
        if (window.radius != null) {
            if (window.radius.automatic()) {
                b.automaticWindowRadius(true);
            } else {
                b.windowRadius(window.radius.radius());
            }
        }
        if (window.pqReplicas != null) {
            b.pqReplicas(window.pqReplicas);
        }
        if (window.placement != null) {
            b.windowPlacement(window.placement);
        }
        if (window.skinUmPerTexcoord != null) {
            double[] t = window.skinUmPerTexcoord;
            if (t.length < 1 || t.length > 2) {
                throw new InvalidSettingException(Quantity.SCAN_TILING, "give one number or two, U,V; got "
                        + t.length);
            }
            b.scanTiling(new ScanTiling(t[0], t[t.length - 1], base.window().tiling().columnsAlongV()));
        }
        SpectralSettings s = base.spectral();
        if (spectral.minNm != null || spectral.maxNm != null || spectral.stepNm != null
                || spectral.normalisation != null) {
            b.spectral(new SpectralSettings(or(spectral.minNm, s.lambdaMinNm()), or(spectral.maxNm, s.lambdaMaxNm()),
                    or(spectral.stepNm, s.lambdaStepNm()), spectral.normalisation != null ? spectral.normalisation
                    : s.normalisation()));
        }
        IlluminationSettings i = base.illumination();
        if (illumination.coherenceLengthUm != null) {
            b.coherenceLengthUm(illumination.coherenceLengthUm);
        }
        if (illumination.refractiveIndex != null) {
            b.material(illumination.refractiveIndex);
        }
        if (illumination.lightSizeDeg != null) {
            b.lightSizeDeg(illumination.lightSizeDeg);
        }
        if (illumination.lightProfile != null) {
            b.lightProfile(illumination.lightProfile);
        }
        if (illumination.gain != null || illumination.fresnel != null) {
            b.gain(illumination.gain != null ? illumination.gain : illumination.fresnel);
        }
        if (illumination.pixelFilter != null) {
            b.pixelFilter(illumination.pixelFilter);
        }
        if (lobes.quadrature != null) {
            b.lobes(lobes.quadrature.applyTo(base.lobes()));
        }
        if (gpu.termFormat != null) {
            b.termFormat(gpu.termFormat);
        }
        if (gpu.bakedSamples != null) {
            b.bakedSamples(gpu.bakedSamples.uv(), gpu.bakedSamples.w());
        }
        if (rigorous.harmonics != null || rigorous.layers != null || rigorous.noExtrapolation
                || rigorous.polarisation != null || rigorous.orders != null) {
            b.rigorous(rigorousSettings(base.rigorous()));
        }
        return b.build();
    }

    private RigorousSettings rigorousSettings(RigorousSettings base) {
        Resolution r = base.resolution();
        int maxOrder = rigorous.harmonics != null ? rigorous.harmonics.maxOrder() : r.maxOrder();
        int layers = rigorous.layers != null ? rigorous.layers : r.layers();
        boolean extrapolate = !rigorous.noExtrapolation && r.extrapolate();
        if (maxOrder > Resolution.MAX_ORDER || maxOrder < 0) {
            throw new InvalidSettingException(Quantity.HARMONICS, "the highest harmonic must be in [1, "
                    + Resolution.MAX_ORDER + "] or auto, got " + maxOrder);
        }
        if (layers < 1 || layers > Resolution.MAX_LAYERS) {
            throw new InvalidSettingException(Quantity.LAYERS, "the staircase's layers must be in [1, "
                    + Resolution.MAX_LAYERS + "], got " + layers);
        }
        if (extrapolate && layers % 2 != 0) {
            throw new InvalidSettingException(Quantity.LAYERS, "the staircase is extrapolated from L / 2 and L "
                    + "layers: give an even L, or add --no-layer-extrapolation; got " + layers);
        }
        return new RigorousSettings(new Resolution(maxOrder, layers, extrapolate),
                rigorous.polarisation != null ? rigorous.polarisation : base.polarisation(),
                rigorous.orders != null ? rigorous.orders : base.orders());
    }

    private static double or(Double given, double fallback) {
        return given != null ? given : fallback;
    }

    /** The variant asked for, or {@code fallback} when none (or auto) was given. */
    public Variant variantOr(Variant fallback) {
        return variant == null || variant.auto() ? fallback : variant.variant();
    }
}
