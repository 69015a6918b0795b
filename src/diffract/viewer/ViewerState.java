package diffract.viewer;

import diffract.optics.BrdfSettings;
import diffract.optics.TaylorTerms;

import java.util.Objects;

/**
 * One immutable snapshot of everything the user changes while the viewer runs. The controller and the background
 * workers replace it as a whole ({@link ViewerModel#update}); the render thread reads one per frame.
 *
 * @param settings    the BRDF settings asked for; N may exceed what {@code terms} hold while more are precomputed
 * @param terms       the Taylor terms at hand (0..terms.highestOrder())
 * @param precompute  the background precompute under way, or null
 * @param notice      a transient message for the title, or null
 */
public record ViewerState(BrdfSettings settings, OrbitCamera camera, LightDirection light, double exposure,
                          DisplayMode mode, boolean pigmentationOn, TaylorTerms terms, PrecomputeProgress precompute,
                          Notice notice) {
    public ViewerState {
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(camera, "camera");
        Objects.requireNonNull(light, "light");
        Objects.requireNonNull(mode, "mode");
        Objects.requireNonNull(terms, "terms");
    }

    /**
     * What the shaders can draw now: the settings asked for, with N lowered to the terms at hand, so the window
     * keeps drawing with the old terms while more are precomputed.
     */
    public BrdfSettings drawableSettings() {
        return settings.highestOrder() <= terms.highestOrder() ? settings
                : settings.withHighestOrder(terms.highestOrder());
    }

    /** Whether the settings ask for more terms than are at hand. */
    public boolean needsMoreTerms() {
        return settings.highestOrder() > terms.highestOrder();
    }

    public ViewerState withSettings(BrdfSettings s) {
        return new ViewerState(s, camera, light, exposure, mode, pigmentationOn, terms, precompute, notice);
    }

    public ViewerState withCamera(OrbitCamera c) {
        return new ViewerState(settings, c, light, exposure, mode, pigmentationOn, terms, precompute, notice);
    }

    public ViewerState withLight(LightDirection l) {
        return new ViewerState(settings, camera, l, exposure, mode, pigmentationOn, terms, precompute, notice);
    }

    public ViewerState withExposure(double e) {
        return new ViewerState(settings, camera, light, e, mode, pigmentationOn, terms, precompute, notice);
    }

    public ViewerState withMode(DisplayMode m) {
        return new ViewerState(settings, camera, light, exposure, m, pigmentationOn, terms, precompute, notice);
    }

    public ViewerState withPigmentationOn(boolean on) {
        return new ViewerState(settings, camera, light, exposure, mode, on, terms, precompute, notice);
    }

    public ViewerState withTerms(TaylorTerms t) {
        return new ViewerState(settings, camera, light, exposure, mode, pigmentationOn, t, precompute, notice);
    }

    public ViewerState withPrecompute(PrecomputeProgress p) {
        return new ViewerState(settings, camera, light, exposure, mode, pigmentationOn, terms, p, notice);
    }

    public ViewerState withNotice(Notice n) {
        return new ViewerState(settings, camera, light, exposure, mode, pigmentationOn, terms, precompute, n);
    }
}
