package diffract.viewer;

import diffract.optics.BrdfSettings;
import diffract.optics.LightPolicy;
import diffract.optics.TaylorTerms;
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
    /** How the user looks at the patch: the orbit camera, the light, the exposure, the mode, the pigmentation. */
    public record View(OrbitCamera camera, LightDirection light, double exposure, DisplayMode mode,
                       boolean pigmentationOn) {
        public View {
            Objects.requireNonNull(camera, "camera");
            Objects.requireNonNull(light, "light");
            Objects.requireNonNull(mode, "mode");
        }

        public View withCamera(OrbitCamera c) { return new View(c, light, exposure, mode, pigmentationOn); }

        public View withLight(LightDirection l) { return new View(camera, l, exposure, mode, pigmentationOn); }

        public View withExposure(double e) { return new View(camera, light, e, mode, pigmentationOn); }

        public View withMode(DisplayMode m) { return new View(camera, light, exposure, m, pigmentationOn); }

        public View withPigmentationOn(boolean on) { return new View(camera, light, exposure, mode, on); }
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
