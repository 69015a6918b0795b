package diffract.optics;

import diffract.optics.illumination.IlluminationSettings;
import diffract.optics.illumination.LightSource;
import diffract.optics.patches.ScanTiling;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.LightProfile;
import diffract.optics.settings.OrderWeights;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.Quantity;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.settings.TermFormat;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.spectra.TaylorSettings;
import diffract.optics.spectra.WindowSettings;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.windows.WindowRadii;

import java.util.function.Consumer;

/**
 * Everything that decides how a variant evaluates the BRDF, by concern: the spectral model, the Taylor
 * approximation, the window between DFT texels, the illumination (coherence, light size, pixel filter, the surface's
 * index, the gain model), the lobes method's quadrature, the GPU's tables and the rigorous method's resolution. Each
 * group checks its own ranges; {@link Builder} is the one way to make or change settings. The defaults are the
 * thesis' configuration (001 implementation notes; 003 sec. 1.3.2): 30 Taylor terms, a 3 x 3 window, 5 nm steps over
 * 380-780 nm, 4 sigma_s = 65 um, float32 terms, a point light and point-sampled map pixels; where the physics measured
 * since says otherwise, the surface is keratin (n = 1.56, the thesis took 1.5) and the gain model Rayleigh-Rice's
 * ({@link GainModel}; docs/design/rigorous.md). The reference reads only the spectral range and the illumination.
 *
 * <p>A new setting goes into the group of its concern (a new group into this record and {@link Builder}); a new
 * variant into {@link Variant}.
 */
public record BrdfSettings(Variant variant, SpectralSettings spectral, TaylorSettings taylor, WindowSettings window,
                           IlluminationSettings illumination, LobeQuadrature lobes, GpuTableSettings gpu,
                           RigorousSettings rigorous) {

    public BrdfSettings {
        if (variant == null || spectral == null || taylor == null || window == null || illumination == null
                || lobes == null || gpu == null || rigorous == null) {
            throw new NullPointerException("the variant and every group of settings are required");
        }
        if (window.placement() == WindowPlacement.LOCAL && !variant.drawsLocalWindow()) {
            throw new InvalidSettingException(Quantity.WINDOW_PLACEMENT, DiffractionBrdf.LOCAL_NEEDS_FLSS_OR_NMM);
        }
        if (rigorous.orders() == OrderWeights.RIGOROUS && !variant.takesRigorousOrders()) {
            throw new InvalidSettingException(Quantity.ORDERS, variant.drawsTable()
                    ? "the rigorous orders depend on the light's direction, which a baked table (a function of "
                    + "-omega_i - omega_r alone) does not hold: draw them with " + Methods.listed(
                    Variant::takesRigorousOrders, "or")
                    : variant.label() + " draws the scalar model's orders; the rigorous orders are drawn by "
                    + Methods.listed(Variant::takesRigorousOrders, "or") + " (and the rigorous method is Maxwell's "
                    + "equations throughout)");
        }
    }

    /** The thesis' configuration for a variant. */
    public static BrdfSettings thesis(Variant variant) {
        return new BrdfSettings(variant, SpectralSettings.thesis(), TaylorSettings.thesis(), WindowSettings.thesis(),
                IlluminationSettings.thesis(), LobeQuadrature.DEFAULT, GpuTableSettings.exact(), RigorousSettings.DEFAULT);
    }

    /** A builder that starts from the thesis' configuration for {@code variant}. */
    public static Builder builder(Variant variant) {
        return thesis(variant).toBuilder();
    }

    /** A builder that starts from these settings. */
    public Builder toBuilder() {
        return new Builder(this);
    }

    /** These settings changed by {@code change}, e.g. {@code settings.with(b -> b.highestOrder(20))}. */
    public BrdfSettings with(Consumer<Builder> change) {
        Builder b = toBuilder();
        change.accept(b);
        return b.build();
    }

    /**
     * These settings for a picture shown at {@code exposure}: the lobes method's cutoff scaled to what the display
     * shows ({@link LobeQuadrature#shownAt}).
     */
    public BrdfSettings shownAt(double exposure) {
        LobeQuadrature shown = lobes.shownAt(exposure);
        return shown == lobes ? this : with(b -> b.lobes(shown));
    }

    /** The coherence window of the illumination, placed as the window settings say. */
    public CoherenceWindow coherenceWindow() {
        return new CoherenceWindow(illumination.sigmaSpatialUm(), window.placement());
    }

    /** The window radii per axis for a patch of this extent (fixed, or automatic from sigma_f). */
    public WindowRadii windowRadii(double extentXUm, double extentYUm) {
        return window.radii(coherenceWindow(), extentXUm, extentYUm);
    }

    /** The highest Taylor order any lookup of a patch of this height uses ({@link TaylorSettings#highestOrderNeeded}). */
    public int highestOrderNeeded(double maxAbsHeightUm) {
        return taylor.highestOrderNeeded(spectral.lambdaMinNm(), maxAbsHeightUm);
    }

    /**
     * Makes and changes settings one value or one group at a time; {@link #build} checks the groups' ranges.
     * Values are kept per group, so the groups are the single place that lists their components.
     */
    public static final class Builder {
        private Variant variant;
        private SpectralSettings spectral;
        private TaylorSettings taylor;
        private WindowSettings window;
        private IlluminationSettings illumination;
        private LobeQuadrature lobes;
        private GpuTableSettings gpu;
        private RigorousSettings rigorous;

        private Builder(BrdfSettings s) {
            variant = s.variant;
            spectral = s.spectral;
            taylor = s.taylor;
            window = s.window;
            illumination = s.illumination;
            lobes = s.lobes;
            gpu = s.gpu;
            rigorous = s.rigorous;
        }

        public Builder variant(Variant v) {
            variant = v;
            return this;
        }

        /**
         * The method {@code v} for a picture the program draws on its own (a table for the environment's lights, the
         * preview, a fallback): the rigorous orders are kept where {@code v} takes them and become the scalar ones
         * where it does not, where {@link #variant} with the rigorous orders refuses such a method as the user's
         * choice.
         */
        public Builder drawnBy(Variant v) {
            variant = v;
            if (rigorous.orders() == OrderWeights.RIGOROUS && !v.takesRigorousOrders()) {
                rigorous = rigorous.withOrders(OrderWeights.SCALAR);
            }
            return this;
        }

        /** The spectral model as a whole. */
        public Builder spectral(SpectralSettings s) {
            spectral = s;
            return this;
        }

        /** The wavelength range [min, max] in nm. */
        public Builder lambdaRangeNm(double minNm, double maxNm) {
            return spectral(new SpectralSettings(minNm, maxNm, spectral.lambdaStepNm(), spectral.normalisation()));
        }

        public Builder lambdaStepNm(double stepNm) {
            return spectral(new SpectralSettings(spectral.lambdaMinNm(), spectral.lambdaMaxNm(), stepNm,
                    spectral.normalisation()));
        }

        /** The Taylor approximation as a whole. */
        public Builder taylor(TaylorSettings t) {
            taylor = t;
            return this;
        }

        /** N: terms n = 0..N. */
        public Builder highestOrder(int n) {
            return taylor(new TaylorSettings(n, taylor.tolerance(), taylor.expansion()));
        }

        /** Each lookup's early stop (0 = always N). */
        public Builder taylorTolerance(double tolerance) {
            return taylor(new TaylorSettings(taylor.highestOrder(), tolerance, taylor.expansion()));
        }

        public Builder expansion(TaylorExpansion expansion) {
            return taylor(new TaylorSettings(taylor.highestOrder(), taylor.tolerance(), expansion));
        }

        /** The window as a whole. */
        public Builder window(WindowSettings w) {
            window = w;
            return this;
        }

        /** A fixed window radius R (the automatic radius off). */
        public Builder windowRadius(int r) {
            return window(new WindowSettings(r, false, window.pqReplicas(), window.placement(), window.tiling()));
        }

        /** The window radius per axis from sigma_f (true), or the fixed radius (false). */
        public Builder automaticWindowRadius(boolean automatic) {
            return window(new WindowSettings(window.radius(), automatic, window.pqReplicas(), window.placement(),
                    window.tiling()));
        }

        /** Where the coherence window sits: averaged over its position, or fixed at the DFT's origin. */
        public Builder windowPlacement(WindowPlacement placement) {
            return window(new WindowSettings(window.radius(), window.automatic(), window.pqReplicas(), placement,
                    window.tiling()));
        }

        /** How the scan lies on a mesh's texture coordinates (the local window's). */
        public Builder scanTiling(ScanTiling tiling) {
            return window(new WindowSettings(window.radius(), window.automatic(), window.pqReplicas(),
                    window.placement(), tiling));
        }

        public Builder pqReplicas(int replicas) {
            return window(new WindowSettings(window.radius(), window.automatic(), replicas, window.placement(),
                    window.tiling()));
        }

        /** The illumination as a whole. */
        public Builder illumination(IlluminationSettings i) {
            illumination = i;
            return this;
        }

        /** The coherence length 4 sigma_s in um. */
        public Builder coherenceLengthUm(double um) {
            return illumination(illumination.withCoherenceLengthUm(um));
        }

        public Builder refractiveIndex(double n) {
            return illumination(illumination.withRefractiveIndex(n));
        }

        /** The surface's complex index n + i k. */
        public Builder material(diffract.optics.rigorous.ComplexIndex index) {
            return illumination(illumination.withMaterial(index));
        }

        /** The light's angular diameter in degrees (0: a point light), its profile kept. */
        public Builder lightSizeDeg(double diameterDeg) {
            return illumination(illumination.withLight(new LightSource(diameterDeg, illumination.light().profile())));
        }

        /** The light's profile, its diameter kept. */
        public Builder lightProfile(LightProfile profile) {
            return illumination(illumination.withLight(illumination.light().withProfile(profile)));
        }

        public Builder gain(GainModel model) {
            return illumination(illumination.withGain(model));
        }

        public Builder pixelFilter(PixelFilter filter) {
            return illumination(illumination.withPixelFilter(filter));
        }

        /** The lobes method's quadrature as a whole. */
        public Builder lobes(LobeQuadrature quadrature) {
            lobes = quadrature;
            return this;
        }

        /** The GPU tables as a whole. */
        public Builder gpu(GpuTableSettings g) {
            gpu = g;
            return this;
        }

        public Builder termFormat(TermFormat format) {
            return gpu(new GpuTableSettings(format, gpu.bakedUvSamples(), gpu.bakedWSamples()));
        }

        /** The baked table's samples along u and v (each) and along w; 0 = automatic. */
        public Builder bakedSamples(int uvSamples, int wSamples) {
            return gpu(new GpuTableSettings(gpu.termFormat(), uvSamples, wSamples));
        }

        /** The rigorous method's settings as a whole. */
        public Builder rigorous(RigorousSettings r) {
            rigorous = r;
            return this;
        }

        public BrdfSettings build() {
            return new BrdfSettings(variant, spectral, taylor, window, illumination, lobes, gpu, rigorous);
        }
    }
}
