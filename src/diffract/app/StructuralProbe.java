package diffract.app;

import diffract.jrtr.OffscreenTarget;
import diffract.render.FrameOutput;
import diffract.scene.DisplayMode;
import diffract.scene.SceneSetup;
import diffract.util.Reporter;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;

import java.util.Arrays;

/**
 * The structural colour of a scene's picture by itself: the frame drawn with the pigment off as linear light (after
 * the tone mapping's exposure stops, before its operator), and the shape's pixels (its mask; a BRDF map's every
 * pixel), at half the picture's size in each direction (a quarter of its cost). What {@code --exposure auto} and the
 * dark-picture notice of a still read.
 *
 * @param brightestY the largest luminance Y of the shape's pixels per unit of exposure
 * @param brightY    the 99th percentile of Y among the shape's lit pixels (above 1e-3 of the brightest), per unit of
 *                   exposure: what {@code --exposure auto} maps to 1, a few pixels of specular highlight aside
 * @param shapePixels the pixels of the probe that show the shape
 */
record StructuralProbe(double brightestY, double brightY, int shapePixels) {
    /** The share of the lit pixels above the one auto maps to 1. */
    static final double BRIGHT_FRACTION = 0.01;

    static StructuralProbe of(SceneSetup setup, int width, int height, Reporter reporter) {
        int w = Math.max(1, width / 2);
        int h = Math.max(1, height / 2);
        ViewerModel model = ViewerModel.load(setup, Reporter.SILENT);
        model.bakeIfNeeded(reporter);
        model.update(s -> s.withView(s.view().withPigmentationOn(false)));
        ViewerRenderer renderer = new ViewerRenderer(model, FrameOutput.LINEAR);
        float[] linear;
        float[] mask;
        try (OffscreenTarget target = new OffscreenTarget(renderer)) {
            linear = target.renderRgb(w, h);
            if (setup.mode() == DisplayMode.BRDF_MAP) {
                mask = null;
            } else {
                renderer.setMaskOnly(true);
                mask = target.renderRgb(w, h);
            }
        }
        return of(linear, mask, setup.exposure());
    }

    /** From a linear frame (RGB) and the shape's mask (RGB, white on black; null: every pixel) at {@code exposure}. */
    static StructuralProbe of(float[] linearRgb, float[] maskRgb, double exposure) {
        int pixels = linearRgb.length / 3;
        double[] y = new double[pixels];
        int count = 0;
        double brightest = 0;
        for (int p = 0; p < pixels; p++) {
            if (maskRgb != null && maskRgb[3 * p] < 0.5f) {
                continue;
            }
            double value = 0.2126 * linearRgb[3 * p] + 0.7152 * linearRgb[3 * p + 1] + 0.0722 * linearRgb[3 * p + 2];
            value = Double.isFinite(value) ? Math.max(value, 0) : 0;
            y[count++] = value;
            brightest = Math.max(brightest, value);
        }
        double threshold = 1e-3 * brightest;
        double[] lit = Arrays.stream(y, 0, count).filter(v -> v > threshold && v > 0).sorted().toArray();
        double bright = lit.length == 0 ? 0 : lit[Math.min(lit.length - 1, (int) Math.floor((1 - BRIGHT_FRACTION)
                * lit.length))];
        return new StructuralProbe(brightest / exposure, bright / exposure, count);
    }

    /** The exposure that shows {@link #brightY} as 1, or {@code fallback} when nothing is lit. */
    double autoExposure(double fallback) {
        return brightY > 0 && Double.isFinite(brightY) ? 1 / brightY : fallback;
    }
}
