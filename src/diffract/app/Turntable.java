package diffract.app;

import diffract.jrtr.OffscreenTarget;
import diffract.render.ShortPixels;
import diffract.scene.OrbitCamera;
import diffract.scene.Scene;
import diffract.util.AnimatedGif;
import diffract.util.ImageFiles;
import diffract.util.Reporter;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * {@code render --turntable FRAMES}: the camera (or, with {@code --orbit-light}, the key light and the environment)
 * goes once round the world y axis in FRAMES equal steps, frame k at 360 k / FRAMES degrees; the frames become a
 * looping GIF or a PNG sequence OUT-000.png, OUT-001.png, ...
 */
final class Turntable {
    private Turntable() {
    }

    /** All FRAMES frames into {@code output}: a GIF, or the PNG sequence written frame by frame as it goes. */
    static void render(OffscreenTarget target, ViewerRenderer renderer, ViewerModel model, int frames,
                       boolean orbitLight, Path output, Scene.ImageSize size, int frameMs, ShortPixels shortPixels,
                       Reporter reporter) throws IOException {
        boolean gif = isGif(output);
        List<float[]> pictures = new ArrayList<>();
        render(target, renderer, model, frames, orbitLight, 0, frames, size, shortPixels, reporter, (k, rgb) -> {
            if (gif) {
                pictures.add(rgb);
            } else {
                ImageFiles.writePng(sequenceName(output, k), rgb, size.width(), size.height(), 3);
            }
        });
        if (gif) {
            write(output, pictures, size, frameMs);
        }
    }

    /** What becomes of frame k's linear floats (RGB, rows from the top). */
    @FunctionalInterface
    interface FrameSink {
        void accept(int k, float[] rgb) throws IOException;
    }

    /**
     * Frames {@code from} to {@code to - 1} of FRAMES: frame k at 360 k / FRAMES degrees from the model's own view,
     * so that any run of frames is drawn as the whole turntable draws it; {@code shortPixels} counts their pixels left
     * short.
     */
    static void render(OffscreenTarget target, ViewerRenderer renderer, ViewerModel model, int frames,
                       boolean orbitLight, int from, int to, Scene.ImageSize size, ShortPixels shortPixels,
                       Reporter reporter, FrameSink sink) throws IOException {
        OrbitCamera start = model.state().view().camera();
        for (int k = from; k < to; k++) {
            double degrees = 360.0 * k / frames;
            if (orbitLight) {
                renderer.setLightTurnDeg(degrees);
            } else {
                model.update(s -> s.withView(s.view().withCamera(start.orbitedBy(degrees, 0))));
            }
            sink.accept(k, shortPixels.rgbOf(target.renderRgba(size.width(), size.height())));
            reporter.progress("turntable", (k - from + 1.0) / (to - from));
        }
    }

    /** Every frame, in order, into {@code output}: what {@link #render} writes, from frames drawn elsewhere. */
    static void write(Path output, List<float[]> frames, Scene.ImageSize size, int frameMs) throws IOException {
        if (isGif(output)) {
            AnimatedGif.write(output, frames, size.width(), size.height(), frameMs);
            return;
        }
        for (int k = 0; k < frames.size(); k++) {
            ImageFiles.writePng(sequenceName(output, k), frames.get(k), size.width(), size.height(), 3);
        }
    }

    private static boolean isGif(Path output) {
        return output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gif");
    }

    /** OUT.png -> OUT-007.png. */
    static Path sequenceName(Path output, int k) {
        String name = output.getFileName().toString();
        String stem = name.substring(0, name.length() - 4);
        return output.resolveSibling(String.format(Locale.ROOT, "%s-%03d.png", stem, k));
    }
}
