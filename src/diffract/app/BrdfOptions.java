package diffract.app;

import diffract.colour.MirrorNormalisation;
import diffract.optics.BrdfSettings;
import diffract.optics.FresnelModel;
import diffract.optics.IlluminationSettings;
import diffract.optics.LightProfile;
import diffract.optics.LightSource;
import diffract.optics.PixelFilter;
import diffract.optics.SpectralSettings;
import diffract.optics.TaylorExpansion;
import diffract.optics.TermFormat;
import diffract.optics.Variant;
import diffract.optics.InvalidSettingException;
import diffract.optics.Quantity;
import diffract.optics.ScanTiling;
import diffract.optics.WindowPlacement;
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
final class BrdfOptions {
    @Option(names = "--variant", paramLabel = "V", converter = OptionTypes.VariantChoice.Converter.class,
            completionCandidates = OptionTypes.VariantChoice.Candidates.class,
            description = "${COMPLETION-CANDIDATES}: the exact CPU reference, the thesis' three shader "
                    + "approximations, the baked table (baked(of=lobes) or baked(of=flss) names the method it holds), "
                    + "the Gaussian lobes (pixel- and light-averaged, exact in wavelength), or auto, the cheapest "
                    + "configuration whose measured error on this patch meets --max-delta-e (default: reference on "
                    + "brdfmap, lobes on view and render).")
    OptionTypes.VariantChoice variant;

    @Option(names = "--max-delta-e", paramLabel = "DE",
            description = "With --variant auto: the accuracy target, mean CIEDE2000 against the reference over the "
                    + "lit pixels.")
    Double maxDeltaE;

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

    /** {@link diffract.optics.TaylorSettings}. */
    static final class Taylor {
        @Option(names = "--terms", paramLabel = "N", description = "Highest Taylor order N, terms n = 0..N (default 30).")
        Integer highestOrder;

        @Option(names = "--taylor-tolerance", paramLabel = "EPS",
                description = "Stop each lookup's Taylor loop at the first order whose Lagrange bound "
                        + "x^(n+1) e^x/(n+1)! (x = k|w|max|h|) is <= EPS; 0 = always N (default 0).")
        Double tolerance;

        @Option(names = "--expansion", paramLabel = "E",
                description = "auto (default: the thesis' series around 0 where the patch lets it reach 1e-3 in P, "
                        + "else around the nearest of several phase centres), plain or centred. With --variant auto "
                        + "the default is plain: the path its calibration measured.")
        TaylorExpansion expansion;
    }

    /** {@link diffract.optics.WindowSettings}. */
    static final class Window {
        @Option(names = "--window-radius", paramLabel = "R|auto", converter = OptionTypes.WindowRadius.Converter.class,
                description = "Window of (2R+1)^2 texels (default 1); auto: per axis the smallest R capturing "
                        + "99.73 %% of the Gaussian window's weight (sigma_f in texels).")
        OptionTypes.WindowRadius radius;

        @Option(names = "--pq-replicas", paramLabel = "R", description = "PQ replicas per axis; 0 spans the coherence length (default 0).")
        Integer pqReplicas;

        @Option(names = "--window", paramLabel = "W", completionCandidates = OptionTypes.WindowPlacementNames.class,
                description = "${COMPLETION-CANDIDATES}: the BRDF averaged over where the coherence window sits on "
                        + "the surface (default: what a pixel or a light wider than a coherence area sees; texels add "
                        + "as powers), one window at the DFT's origin, as the thesis (for comparisons), or local: the "
                        + "window under each surface point of a mesh, averaged over the pixel's footprint on the skin "
                        + "(glints of a close-up; flss and nmm on surfaces, with --skin-um-per-texcoord).")
        WindowPlacement placement;

        @Option(names = "--skin-um-per-texcoord", paramLabel = "U[,V]", split = ",", hideParamSyntax = true,
                description = "For --window local: micrometres of skin one unit of the mesh's texture coordinates "
                        + "spans, along u and v (one number: both); the scan repeats every L / U along u.")
        double[] skinUmPerTexcoord;
    }

    /** {@link SpectralSettings}. */
    static final class Spectral {
        @Option(names = "--lambda-min", paramLabel = "NM", description = "Shortest wavelength (default 380, within 360..830).")
        Double minNm;

        @Option(names = "--lambda-max", paramLabel = "NM", description = "Longest wavelength (default 780, within 360..830).")
        Double maxNm;

        @Option(names = "--lambda-step", paramLabel = "NM", description = "Step of flss and pq, nmm's fallback step (default 5).")
        Double stepNm;

        @Option(names = "--normalisation", paramLabel = "M", completionCandidates = OptionTypes.NormalisationNames.class,
                description = "${COMPLETION-CANDIDATES}: a flat mirror's point-sampled peak is D65 white (default, the "
                        + "thesis; the light its lobe reflects then grows as lambda^2) or the light it reflects is "
                        + "(Stam's k^2, what radiometric scenes use).")
        MirrorNormalisation normalisation;
    }

    /** {@link IlluminationSettings}. */
    static final class Illumination {
        @Option(names = "--coherence-length", paramLabel = "UM",
                description = "4 sigma_s of the Gaussian coherence window (default 65, filtered sunlight).")
        Double coherenceLengthUm;

        @Option(names = "--refractive-index", paramLabel = "N", description = "For Schlick's Fresnel term (default 1.5).")
        Double refractiveIndex;

        @Option(names = "--pixel-filter", paramLabel = "F", completionCandidates = OptionTypes.PixelFilterNames.class,
                description = "${COMPLETION-CANDIDATES}: a pixel shows the average over its footprint (default) or "
                        + "the BRDF at its centre, as the thesis' maps (aliases orders narrower than a pixel). "
                        + "Honoured by lobes and the reference.")
        PixelFilter pixelFilter;

        @Option(names = "--fresnel", paramLabel = "F", completionCandidates = OptionTypes.FresnelNames.class,
                description = "${COMPLETION-CANDIDATES}: Schlick's reflectance counted once (default) or squared, as "
                        + "the thesis' eq. cfact prints it (for comparisons).")
        FresnelModel fresnel;

        @Option(names = "--light-size-deg", paramLabel = "DEG",
                description = "Angular diameter of the light, 0.." + (int) LightSource.MAX_DIAMETER_DEG + " degrees, of "
                        + "the profile --light-profile names (default: 0, a point light, on brdfmap; the sun's 0.53 on "
                        + "view, render and in scenes). Rendered by lobes, baked and the reference.")
        Double lightSizeDeg;

        @Option(names = "--light-profile", paramLabel = "P", completionCandidates = OptionTypes.LightProfileNames.class,
                description = "${COMPLETION-CANDIDATES}: the light of --light-size-deg as a uniform disc of diameter D "
                        + "(default: the reference integrates every direction; lobes averages each lobe over the disc "
                        + "with C, S and w per direction; baked integrates it over a table of the point light) or a "
                        + "Gaussian of sigma D/4 per axis linearised about its centre (for comparisons).")
        LightProfile lightProfile;
    }

    /** {@link diffract.optics.LobeQuadrature}. */
    static final class Lobes {
        @Option(names = "--lobe-quadrature", paramLabel = "K=V[,K=V]",
                converter = OptionTypes.LobeQuadratureChange.Converter.class,
                description = "The lobes method's accuracy knobs (docs/filtering.md): nodesPerSigma (default 0.67), "
                        + "maxStepNm (1, 2, 4, 8 or 16; default 8), reachSigmas (2..10; default 4), weightStepNm "
                        + "(default 8), pairThreshold (default 1e-4), lightNodes (1..8; default 3), cutoff (a lobe's largest "
                        + "contribution, of white, below which it is skipped; default 3e-6), weightTolerance (of the "
                        + "tabulated lobe weights; default 1e-4), sumNodesPerBox (wavelength nodes per lobe's passage through "
                        + "the pixel, where scans wider than the window are summed over texels; 0 marches lobe by lobe; "
                        + "default 2).")
        OptionTypes.LobeQuadratureChange quadrature;
    }

    /** {@link diffract.optics.GpuTableSettings}. */
    static final class GpuTables {
        @Option(names = "--texture-format", paramLabel = "F",
                description = "Storage of the Taylor terms: rg32f (default, exact), rg16f (half precision) or rg8 "
                        + "(the thesis' [0, 1]-normalised bytes, 003 eq. 1.1).")
        TermFormat termFormat;

        @Option(names = "--baked-samples", paramLabel = "UV,W", converter = OptionTypes.BakedSamples.Converter.class,
                description = "baked: table samples along u and v (each) and along w; 0 = automatic (default 0,0).")
        OptionTypes.BakedSamples bakedSamples;
    }

    boolean auto() {
        return variant != null && variant.auto();
    }

    /** Whether N was given (it replaces a scene's tolerance-chosen N). */
    boolean highestOrderGiven() {
        return taylor.highestOrder != null;
    }

    /** Checks the options that go together: an accuracy target exactly with auto. */
    void validate() {
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
    BrdfSettings apply(BrdfSettings base) {
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
        if (illumination.coherenceLengthUm != null || illumination.refractiveIndex != null) {
            b.illumination(i.withCoherenceLengthUm(or(illumination.coherenceLengthUm, i.coherenceLengthUm()))
                    .withRefractiveIndex(or(illumination.refractiveIndex, i.refractiveIndex())));
        }
        if (illumination.lightSizeDeg != null) {
            b.lightSizeDeg(illumination.lightSizeDeg);
        }
        if (illumination.lightProfile != null) {
            b.lightProfile(illumination.lightProfile);
        }
        if (illumination.fresnel != null) {
            b.fresnel(illumination.fresnel);
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
        return b.build();
    }

    private static double or(Double given, double fallback) {
        return given != null ? given : fallback;
    }

    /** The variant asked for, or {@code fallback} when none (or auto) was given. */
    Variant variantOr(Variant fallback) {
        return variant == null || variant.auto() ? fallback : variant.variant();
    }
}
