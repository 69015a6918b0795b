package diffract.app;

import diffract.jrtr.OffscreenTarget;
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

    static void render(OffscreenTarget target, ViewerRenderer renderer, ViewerModel model, int frames,
                       boolean orbitLight, Path output, Scene.ImageSize size, int frameMs, Reporter reporter)
            throws IOException {
        OrbitCamera start = model.state().view().camera();
        List<float[]> pictures = new ArrayList<>();
        boolean gif = output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gif");
        for (int k = 0; k < frames; k++) {
            double degrees = 360.0 * k / frames;
            if (orbitLight) {
                renderer.setLightTurnDeg(degrees);
            } else {
                model.update(s -> s.withView(s.view().withCamera(start.orbitedBy(degrees, 0))));
            }
            float[] rgb = target.renderRgb(size.width(), size.height());
            if (gif) {
                pictures.add(rgb);
            } else {
                ImageFiles.writePng(sequenceName(output, k), rgb, size.width(), size.height(), 3);
            }
            reporter.progress("turntable", (k + 1.0) / frames);
        }
        if (gif) {
            AnimatedGif.write(output, pictures, size.width(), size.height(), frameMs);
        }
    }

    /** OUT.png -> OUT-007.png. */
    static Path sequenceName(Path output, int k) {
        String name = output.getFileName().toString();
        String stem = name.substring(0, name.length() - 4);
        return output.resolveSibling(String.format(Locale.ROOT, "%s-%03d.png", stem, k));
    }
}
