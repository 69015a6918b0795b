package diffract.viewer.frame;

import diffract.jrtr.OffscreenTarget;
import diffract.optics.BrdfSettings;
import diffract.pipeline.PatchPeriod;
import diffract.scene.DisplayMode;
import diffract.scene.LightDirection;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import diffract.viewer.ViewerState;

import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.ExecutorService;

/**
 * The BRDF map of the current light beside the rendered object, as the BRDF explorers show it: the view's own method
 * and settings drawn offscreen (a GL context of its own, on a background thread) over the directions omega_r of the
 * unit disc, redrawn when the settings, the light or the exposure change. The orders of the patch's strongest period
 * ({@link PatchPeriod}) are labelled where their 550 nm light leaves: omega_r.xy = -omega_i.xy - m lambda / d along
 * the period (m = 0 the specular direction).
 */
public final class MapInset extends JComponent {
    static final int SIZE_PX = 180;
    /** The wavelength whose orders are labelled. */
    static final double LABEL_NM = 550;
    /** Orders labelled: -ORDERS..ORDERS. */
    static final int ORDERS = 2;

    /** What a map is drawn of: the settings as drawn, the light, the exposure. */
    private record Key(BrdfSettings settings, LightDirection light, double exposure) {
    }

    private final ExecutorService drawer = diffract.util.BackgroundThreads.single("diffract-viewer-inset");
    private volatile ViewerModel source;
    private volatile Optional<PatchPeriod> period = Optional.empty();
    private volatile BufferedImage image;
    private volatile Key shown;
    private volatile Key wanted;
    private volatile boolean drawing;
    private volatile int drawn;

    MapInset() {
        setPreferredSize(new Dimension(SIZE_PX, SIZE_PX));
        setMinimumSize(new Dimension(SIZE_PX, SIZE_PX));
        setToolTipText("the BRDF map of the current light: pixel (i, j) is the direction omega_r; the orders of the "
                + "patch's strongest period at 550 nm labelled");
    }

    JPanel titled() {
        JPanel p = new JPanel(new BorderLayout());
        p.setBorder(BorderFactory.createTitledBorder("BRDF map of this light"));
        p.add(this, BorderLayout.CENTER);
        p.setMaximumSize(new Dimension(SIZE_PX + 20, SIZE_PX + 30));
        return p;
    }

    /** Draws the maps of {@code model}'s patch from now on. */
    void follow(ViewerModel model) {
        source = model;
        shown = null;
        drawer.execute(() -> period = PatchPeriod.of(model.setup().patch()));
    }

    void refresh(ViewerState state) {
        ViewerModel model = source;
        if (model == null || state.bake() != null) {
            return; // a table being baked: the map waits for it
        }
        Key key = new Key(state.drawableSettings(), state.view().light(), state.view().exposure());
        wanted = key;
        if (key.equals(shown) || drawing) {
            return;
        }
        drawing = true;
        drawer.execute(() -> draw(model, state, key));
    }

    private void draw(ViewerModel model, ViewerState state, Key key) {
        try {
            ViewerModel copy = new ViewerModel(model.setup(), state.terms());
            copy.update(s -> state.withView(state.view().withMode(DisplayMode.BRDF_MAP).withSplit(null)));
            float[] rgb;
            try (OffscreenTarget target = new OffscreenTarget(new ViewerRenderer(copy))) {
                rgb = target.renderRgb(SIZE_PX, SIZE_PX);
            }
            BufferedImage picture = new BufferedImage(SIZE_PX, SIZE_PX, BufferedImage.TYPE_INT_RGB);
            for (int y = 0; y < SIZE_PX; y++) {
                for (int x = 0; x < SIZE_PX; x++) {
                    int p = 3 * (y * SIZE_PX + x);
                    picture.setRGB(x, y, channel(rgb[p]) << 16 | channel(rgb[p + 1]) << 8 | channel(rgb[p + 2]));
                }
            }
            image = picture;
            shown = key;
            drawn++;
        } catch (RuntimeException e) {
            shown = key; // not again for the same picture
            System.err.println("diffract: the BRDF-map inset failed: " + e.getMessage());
        } finally {
            drawing = false;
            SwingUtilities.invokeLater(this::repaint);
        }
    }

    private static int channel(float v) {
        return Math.max(0, Math.min(255, Math.round(v * 255)));
    }

    /** Maps drawn so far (tests wait for one). */
    public int mapsDrawn() {
        return drawn;
    }

    /** Whether the map shown is of the state's settings, light and exposure. */
    public boolean showsCurrent() {
        Key w = wanted;
        return w != null && w.equals(shown) && !drawing;
    }

    /** The map shown (null before the first). */
    public BufferedImage image() {
        return image;
    }

    /**
     * The orders' labels: (m, column, row) in the map's pixels for the orders of the patch's period at
     * {@link #LABEL_NM} whose direction is above the horizon, for the light (theta_i, phi_i).
     */
    List<int[]> orderLabels(LightDirection light) {
        List<int[]> labels = new ArrayList<>();
        if (period.isEmpty()) {
            return labels;
        }
        PatchPeriod p = period.get();
        var wi = light.direction();
        double step = LABEL_NM * 1e-3 / p.periodUm();
        double az = Math.toRadians(p.azimuthDeg());
        for (int m = -ORDERS; m <= ORDERS; m++) {
            double x = -wi.x() - m * step * Math.cos(az);
            double y = -wi.y() - m * step * Math.sin(az);
            if (Math.hypot(x, y) < 1) {
                // BrdfMap's pixels: column (x + 1) S / 2, row (1 - y) S / 2
                labels.add(new int[] {m, (int) Math.round((x + 1) * SIZE_PX / 2), (int) Math.round((1 - y) * SIZE_PX / 2)});
            }
        }
        return labels;
    }

    @Override
    protected void paintComponent(Graphics g0) {
        Graphics2D g = (Graphics2D) g0.create();
        g.setColor(Color.BLACK);
        g.fillRect(0, 0, getWidth(), getHeight());
        int ox = (getWidth() - SIZE_PX) / 2;
        int oy = (getHeight() - SIZE_PX) / 2;
        BufferedImage picture = image;
        if (picture != null) {
            g.drawImage(picture, ox, oy, null);
        }
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(new Color(120, 120, 130));
        g.drawOval(ox, oy, SIZE_PX - 1, SIZE_PX - 1);
        Key key = shown;
        if (key != null) {
            g.setColor(new Color(255, 255, 255, 200));
            for (int[] label : orderLabels(key.light())) {
                String text = label[0] == 0 ? "0" : (label[0] > 0 ? "+" : "") + label[0];
                g.drawOval(ox + label[1] - 3, oy + label[2] - 3, 6, 6);
                g.drawString(text, ox + label[1] + 5, oy + label[2] - 4);
            }
        }
        if (picture == null || drawing) {
            g.setColor(Color.LIGHT_GRAY);
            g.drawString(picture == null ? "drawing..." : "", 6, 14);
        }
        g.dispose();
    }

    void close() {
        diffract.util.BackgroundThreads.stop(drawer);
    }
}
