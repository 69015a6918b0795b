package diffract.viewer;

import diffract.optics.BrdfSettings;
import diffract.optics.LightPolicy;
import diffract.optics.spectra.TaylorTerms;
import diffract.scene.DisplayMode;
import diffract.scene.LightDirection;
import diffract.scene.OrbitCamera;

import java.util.Objects;

/**
 * One immutable snapshot of everything the user changes while the viewer runs, and of the work under way. The
 * controller and the background workers replace it as a whole ({@link ViewerModel#update}); the render thread reads
 * one per frame.
 *
 * @param settings    the BRDF settings asked for; N may exceed what {@code terms} hold while more are precomputed
 * @param view        camera, light, exposure and what is shown
 * @param terms       the Taylor terms at hand (0..terms.highestOrder())
 * @param precompute  the background precompute under way, or null
 * @param bake        the background bake of the baked table under way, or null
 * @param notice      a transient message for the title, or null
 */
public record ViewerState(BrdfSettings settings, View view, TaylorTerms terms, PrecomputeProgress precompute,
                          BakeProgress bake, Notice notice) {
    /**
     * How the user looks at the patch: the orbit camera, the light, the exposure, the mode, the pigmentation, and an
     * A/B split ({@code null}: the whole picture drawn with the settings).
     */
    public record View(OrbitCamera camera, LightDirection light, double exposure, DisplayMode mode,
                       boolean pigmentationOn, Split split) {
        public View {
            Objects.requireNonNull(camera, "camera");
            Objects.requireNonNull(light, "light");
            Objects.requireNonNull(mode, "mode");
        }

        public View(OrbitCamera camera, LightDirection light, double exposure, DisplayMode mode,
                    boolean pigmentationOn) {
            this(camera, light, exposure, mode, pigmentationOn, null);
        }

        public View withCamera(OrbitCamera c) { return new View(c, light, exposure, mode, pigmentationOn, split); }

        public View withLight(LightDirection l) { return new View(camera, l, exposure, mode, pigmentationOn, split); }

        public View withExposure(double e) { return new View(camera, light, e, mode, pigmentationOn, split); }

        public View withMode(DisplayMode m) { return new View(camera, light, exposure, m, pigmentationOn, split); }

        public View withPigmentationOn(boolean on) { return new View(camera, light, exposure, mode, on, split); }

        public View withSplit(Split s) { return new View(camera, light, exposure, mode, pigmentationOn, s); }
    }

    /**
     * An A/B split of the picture: left of the divider the state's settings (A), right of it {@code other} (B), the
     * same view; each drawn through the same refinement.
     *
     * @param other   the settings of the right part
     * @param divider where the parts meet, as a fraction of the picture's width, in [0, 1]
     */
    public record Split(BrdfSettings other, double divider) {
        public Split {
            Objects.requireNonNull(other, "other");
            divider = Math.max(0, Math.min(1, divider));
        }

        public Split withDivider(double d) {
            return new Split(other, d);
        }

        public Split withOther(BrdfSettings o) {
            return new Split(o, divider);
        }
    }

    /**
     * What the shaders can draw now of the split's settings B ({@link #drawableSettings} for them); null without a
     * split.
     */
    public BrdfSettings drawableSplitSettings() {
        if (view.split() == null) {
            return null;
        }
        BrdfSettings other = view.split().other();
        BrdfSettings withTerms = other.taylor().highestOrder() <= terms.highestOrder() ? other
                : other.with(b -> b.highestOrder(terms.highestOrder()));
        return LightPolicy.of(withTerms).usable();
    }

    public ViewerState {
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(view, "view");
        Objects.requireNonNull(terms, "terms");
    }

    /**
     * What the shaders can draw now: the settings asked for, with N lowered to the terms at hand, so the window
     * keeps drawing with the terms it has while more are precomputed, and a light of finite size drawn as a point
     * by a method that samples the light at its centre ({@link LightPolicy}: the scene's light comes back with the
     * lobes method).
     */
    public BrdfSettings drawableSettings() {
        BrdfSettings withTerms = settings.taylor().highestOrder() <= terms.highestOrder() ? settings
                : settings.with(b -> b.highestOrder(terms.highestOrder()));
        return LightPolicy.of(withTerms).usable();
    }

    /** Whether the settings ask for more terms than are at hand. */
    public boolean needsMoreTerms() {
        return settings.taylor().highestOrder() > terms.highestOrder();
    }

    public ViewerState withSettings(BrdfSettings s) { return new ViewerState(s, view, terms, precompute, bake, notice); }

    public ViewerState withView(View v) { return new ViewerState(settings, v, terms, precompute, bake, notice); }

    public ViewerState withTerms(TaylorTerms t) { return new ViewerState(settings, view, t, precompute, bake, notice); }

    public ViewerState withPrecompute(PrecomputeProgress p) {
        return new ViewerState(settings, view, terms, p, bake, notice);
    }

    public ViewerState withBake(BakeProgress b) { return new ViewerState(settings, view, terms, precompute, b, notice); }

    public ViewerState withNotice(Notice n) { return new ViewerState(settings, view, terms, precompute, bake, n); }
}
