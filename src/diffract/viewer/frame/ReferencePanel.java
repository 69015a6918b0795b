package diffract.viewer.frame;

import diffract.colour.Ciede2000;
import diffract.colour.D65;
import diffract.colour.DeltaEStatistics;
import diffract.colour.Lab;
import diffract.colour.Srgb;
import diffract.colour.Xyz;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.LightSource;
import diffract.optics.patches.HeightField;
import diffract.optics.Methods;
import diffract.optics.settings.OrderWeights;
import diffract.render.GpuBrdfMap;
import diffract.scene.LightDirection;
import diffract.util.DiskCache;
import diffract.util.Reporter;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerState;
import diffract.viewer.ViewerWindow;

import javax.swing.BorderFactory;
import javax.swing.BoxLayout;
import javax.swing.ImageIcon;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.SwingUtilities;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Image;
import java.awt.image.BufferedImage;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.function.Supplier;

/**
 * The view's method against the exact reference, on the BRDF map of the current light (what "users trade speed for
 * accuracy" asks to see): the method's map drawn on the GPU, the CPU yardstick of the same light and settings, both at
 * {@link #SIZE_PX} pixels: the scalar model's exact reference ({@link Methods.Role#EXACT}, 1 nm), or, on a 1-D patch,
 * Maxwell's equations (the rigorous method, its orders solved every 5 nm; a 2-D patch disables it with the reason), and the CIEDE2000 map between them at the view's
 * exposure, with its mean and 95th percentile over the lit pixels (exposed Y above 1 % of white in either, as
 * {@code compare} counts). The reference is computed in the background with its progress and time left, and kept in
 * the disk cache ({@link DiskCache}, kind reference-maps), so a second look at the same light is at once. A light wider
 * than the sun's disc is refused with the reason: the CPU reference integrates a disc many pixels wide at every pixel
 * (hours to days, docs/guide/headless-gl.md).
 */
public final class ReferencePanel extends JPanel {
    /** Pixels per side of the compared maps. */
    static final int SIZE_PX = 64;
    /** The pictures' side on screen. */
    static final int SHOWN_PX = 88;
    /** CIEDE2000 shown white in the error map. */
    static final double ERROR_WHITE = 10;
    /** Bump when the entry's payload changes. */
    static final int FORMAT = 1;

    /** The compared maps and their difference. */
    public record Comparison(BrdfSettings method, LightDirection light, double exposure, float[] methodXyz,
                             float[] referenceXyz, double[] deltaE, DeltaEStatistics statistics, double seconds,
                             Yardstick yardstick) {
    }

    /** What the method is measured against. */
    public enum Yardstick {
        /** The scalar model's exact reference. */
        REFERENCE("the scalar reference"),
        /** Maxwell's equations: the rigorous method (1-D patches and small 2-D cells). */
        RIGOROUS("Maxwell's equations");

        private final String label;

        Yardstick(String label) {
            this.label = label;
        }

        /** The yardstick's settings: the method's, drawn by its variant. */
        BrdfSettings settings(BrdfSettings drawn) {
            return this == REFERENCE ? drawn.with(b -> b.variant(Methods.Role.EXACT.method()).lambdaStepNm(1))
                    : drawn.with(b -> b.variant(Methods.Role.MAXWELL.method()).rigorous(drawn.rigorous()
                            .withOrders(OrderWeights.SCALAR)));
        }

        @Override
        public String toString() {
            return label;
        }
    }

    private final Supplier<ViewerWindow> view;
    private final ExecutorService worker = diffract.util.BackgroundThreads.single("diffract-viewer-reference");
    private final JButton compare = new JButton("Compare with the reference");
    private final JProgressBar progress = new JProgressBar(0, 1000);
    private final JLabel method = picture();
    private final JLabel reference = picture();
    private final JLabel error = picture();
    private final JLabel numbers = new JLabel(" ");
    private final JLabel reason = new JLabel(" ");
    private final JComboBox<Yardstick> yardstick = new JComboBox<>(Yardstick.values());
    /** The patch whose refusal of the rigorous method was last looked at, and that refusal ("" for none). */
    private volatile HeightField refusedPatch;
    private volatile String rigorousRefusal = "";
    private volatile ViewerState state;
    private volatile Comparison last;
    private volatile boolean busy;

    ReferencePanel(Supplier<ViewerWindow> view) {
        this.view = view;
        setLayout(new BoxLayout(this, BoxLayout.Y_AXIS));
        setBorder(BorderFactory.createTitledBorder("Against the reference (BRDF map)"));
        compare.setFocusable(false);
        compare.addActionListener(e -> start());
        yardstick.setFocusable(false);
        yardstick.setName("yardstick");
        yardstick.addActionListener(e -> {
            if (state != null) {
                refresh(state);
            }
        });
        progress.setStringPainted(true);
        progress.setString("");
        JPanel pictures = new JPanel(new FlowLayout(FlowLayout.LEFT, 2, 2));
        pictures.add(captioned(method, "method"));
        pictures.add(captioned(reference, "yardstick"));
        pictures.add(captioned(error, "CIEDE2000"));
        JPanel against = new JPanel(new FlowLayout(FlowLayout.LEFT, 2, 0));
        against.add(new JLabel("against"));
        against.add(yardstick);
        for (Component c : new Component[] {against, compare, progress, pictures, numbers, reason}) {
            ((javax.swing.JComponent) c).setAlignmentX(Component.LEFT_ALIGNMENT);
            add(c);
        }
        setMaximumSize(new Dimension(ViewerFrame.SIDE_WIDTH_PX, 260));
    }

    private static JLabel picture() {
        JLabel l = new JLabel();
        l.setPreferredSize(new Dimension(SHOWN_PX, SHOWN_PX));
        return l;
    }

    private static JPanel captioned(JLabel picture, String caption) {
        JPanel p = new JPanel();
        p.setLayout(new BoxLayout(p, BoxLayout.Y_AXIS));
        p.add(picture);
        p.add(new JLabel(caption));
        return p;
    }

    void refresh(ViewerState s) {
        state = s;
        boolean wide = s.settings().illumination().light().angularDiameterDeg() > LightSource.SUN_DEG + 1e-9;
        String refusal = yardstick.getSelectedItem() == Yardstick.RIGOROUS ? rigorousRefusal() : "";
        compare.setEnabled(!busy && !wide && refusal.isEmpty());
        reason.setText(wide ? "<html><body style='width:230px'>the CPU reference under a "
                + SettingsPanel.number(s.settings().illumination().light().angularDiameterDeg()) + "-degree light "
                + "takes hours to days: compare under the sun (light size 0.53)</body></html>"
                : !refusal.isEmpty() ? "<html><body style='width:230px'>" + refusal + "</body></html>" : " ");
        Comparison c = last;
        if (c != null && !busy && !(c.method().equals(s.drawableSettings()) && c.light().equals(s.view().light())
                && c.exposure() == s.view().exposure())) {
            numbers.setText(String.format(Locale.ROOT, "mean %.2f, p95 %.2f (%d lit px) - of another light or "
                    + "settings", c.statistics().mean(), c.statistics().p95(), c.statistics().pixels()));
        }
    }

    /** Why the view's patch cannot be solved by the rigorous method, or "" where it can; looked at once per patch. */
    private String rigorousRefusal() {
        ViewerWindow v = view.get();
        if (v == null) {
            return "";
        }
        HeightField patch = v.model().setup().patch();
        if (patch != refusedPatch) {
            rigorousRefusal = Methods.Role.MAXWELL.method().fieldRefusal(patch).orElse("");
            refusedPatch = patch;
        }
        return rigorousRefusal;
    }

    /** Picks what the method is measured against (the yardstick's menu). */
    public void against(Yardstick y) {
        yardstick.setSelectedItem(y);
    }

    /** Starts the comparison of the current light and settings in the background (the button's action). */
    public void start() {
        ViewerWindow v = view.get();
        ViewerState s = state;
        Yardstick y = (Yardstick) yardstick.getSelectedItem();
        if (v == null || s == null || busy || (y == Yardstick.RIGOROUS && !rigorousRefusal().isEmpty())) {
            return;
        }
        busy = true;
        compare.setEnabled(false);
        worker.execute(() -> {
            try {
                Comparison c = compare(v.model(), s, y, this::showProgress);
                last = c;
                SwingUtilities.invokeLater(() -> show(c));
            } catch (RuntimeException e) {
                SwingUtilities.invokeLater(() -> numbers.setText("<html><body style='width:230px'>the comparison "
                        + "failed: " + e.getMessage() + "</body></html>"));
            } finally {
                busy = false;
            }
        });
    }

    /** The last comparison finished (null before). */
    public Comparison last() {
        return last;
    }

    public boolean isBusy() {
        return busy;
    }

    /** Whether the compare button is enabled, and the reason shown where it is not. */
    public boolean canCompare() {
        return compare.isEnabled();
    }

    public String reason() {
        return reason.getText();
    }

    private void showProgress(double fraction, double secondsLeft) {
        SwingUtilities.invokeLater(() -> {
            progress.setValue((int) Math.round(1000 * fraction));
            progress.setString(fraction >= 1 ? "done" : String.format(Locale.ROOT, "yardstick %d%%, about %s left",
                    Math.round(100 * fraction), duration(secondsLeft)));
        });
    }

    private static String duration(double seconds) {
        if (!Double.isFinite(seconds)) {
            return "?";
        }
        return seconds < 90 ? Math.round(seconds) + " s" : Math.round(seconds / 60) + " min";
    }

    private void show(Comparison c) {
        method.setIcon(icon(display(c.methodXyz(), c.exposure())));
        reference.setIcon(icon(display(c.referenceXyz(), c.exposure())));
        error.setIcon(icon(errorImage(c.deltaE())));
        numbers.setText(String.format(Locale.ROOT, "<html><body style='width:230px'>CIEDE2000 mean %.2f, p95 %.2f over"
                + " %d lit px (%s against %s, %d px)</body></html>", c.statistics().mean(), c.statistics().p95(),
                c.statistics().pixels(), c.method().variant().spec(), c.yardstick(), SIZE_PX));
        progress.setValue(1000);
        progress.setString(String.format(Locale.ROOT, "%s: %.1f s", c.yardstick(), c.seconds()));
    }

    /** Progress of the reference: the fraction done and the seconds left. */
    interface Progress {
        void at(double fraction, double secondsLeft);
    }

    /**
     * The comparison for the view's state: its method's GPU map and the CPU reference (from the disk cache when it is
     * there), at {@link #SIZE_PX}, and CIEDE2000 at the view's exposure.
     */
    static Comparison compare(ViewerModel model, ViewerState s, Yardstick yardstick, Progress progress) {
        BrdfSettings drawn = s.drawableSettings();
        double exposure = s.view().exposure();
        Direction wi = s.view().light().direction();
        BrdfSettings methodSettings = drawn.shownAt(exposure);
        float[] methodXyz;
        try (GpuBrdfMap map = model.pipeline().gpuMap(methodSettings, methodSettings.spectral().lambdaMinNm(),
                Reporter.SILENT)) {
            methodXyz = map.xyz(wi, SIZE_PX);
        }
        BrdfSettings exact = yardstick.settings(drawn);
        long start = System.nanoTime();
        DiskCache cache = DiskCache.user();
        DiskCache.Key key = new DiskCache.Key("reference-maps", String.join("; ", "viewer reference map format "
                + FORMAT, "patch sha256 " + model.setup().patch().contentSha256(), "omega_i " + wi.x() + " " + wi.y()
                + " " + wi.z(), "size " + SIZE_PX, "settings " + exact));
        float[][] loaded = {cache.load(key, in -> read(in), Reporter.SILENT, "computing the reference map again")};
        double seconds;
        if (loaded[0] == null) {
            DiffractionBrdf brdf = model.pipeline().cpuBrdf(exact, exact.spectral().lambdaMinNm(), Reporter.SILENT);
            loaded[0] = BrdfMap.xyz(brdf, wi, SIZE_PX, new Reporter() {
                @Override
                public void warn(String message) {
                }

                @Override
                public void info(String message) {
                }

                @Override
                public void progress(String task, double fraction) {
                    double elapsed = (System.nanoTime() - start) * 1e-9;
                    progress.at(fraction, fraction > 0 ? elapsed * (1 - fraction) / fraction : Double.NaN);
                }
            });
            float[] computed = loaded[0];
            cache.store(key, out -> write(out, computed), "the reference map", Reporter.SILENT);
        }
        seconds = (System.nanoTime() - start) * 1e-9;
        progress.at(1, 0);
        float[] referenceXyz = loaded[0];
        double[] deltaE = new double[SIZE_PX * SIZE_PX];
        boolean[] lit = new boolean[deltaE.length];
        float[] a = scaled(methodXyz, exposure);
        float[] b = scaled(referenceXyz, exposure);
        Xyz white = D65.whiteXyz();
        for (int p = 0; p < deltaE.length; p++) {
            double x = BrdfMap.xOf(p % SIZE_PX, SIZE_PX);
            double y = BrdfMap.yOf(p / SIZE_PX, SIZE_PX);
            boolean inDisk = x * x + y * y < 1;
            deltaE[p] = inDisk ? Ciede2000.deltaE(Lab.fromXyz(new Xyz(a[3 * p], a[3 * p + 1], a[3 * p + 2]), white),
                    Lab.fromXyz(new Xyz(b[3 * p], b[3 * p + 1], b[3 * p + 2]), white)) : 0;
            lit[p] = inDisk && (a[3 * p + 1] > 0.01 || b[3 * p + 1] > 0.01);
        }
        boolean any = false;
        for (boolean l : lit) {
            any |= l;
        }
        DeltaEStatistics stats = any ? DeltaEStatistics.of(a, b, lit) : new DeltaEStatistics(0, 0, 0, 0, 0);
        return new Comparison(drawn, s.view().light(), exposure, methodXyz, referenceXyz, deltaE, stats, seconds,
                yardstick);
    }

    private static float[] scaled(float[] xyz, double exposure) {
        float[] out = new float[xyz.length];
        for (int i = 0; i < out.length; i++) {
            out[i] = (float) (xyz[i] * exposure);
        }
        return out;
    }

    private static void write(DataOutputStream out, float[] xyz) throws IOException {
        out.writeInt(SIZE_PX);
        DiskCache.writeFloats(out, xyz);
    }

    private static float[] read(DataInputStream in) throws IOException {
        int size = in.readInt();
        if (size != SIZE_PX) {
            throw new IOException("it holds a " + size + " px map, not " + SIZE_PX + " px");
        }
        float[] xyz = new float[3 * SIZE_PX * SIZE_PX];
        DiskCache.readFloats(in, xyz);
        return xyz;
    }

    /** A map of XYZ as display sRGB at the exposure. */
    static BufferedImage display(float[] xyz, double exposure) {
        BufferedImage image = new BufferedImage(SIZE_PX, SIZE_PX, BufferedImage.TYPE_INT_RGB);
        for (int p = 0; p < SIZE_PX * SIZE_PX; p++) {
            double[] rgb = Srgb.linearFromXyz(new Xyz(xyz[3 * p] * exposure, xyz[3 * p + 1] * exposure,
                    xyz[3 * p + 2] * exposure));
            int packed = 0;
            for (double c : rgb) {
                packed = packed << 8 | (int) Math.round(255 * Srgb.encode(Math.max(0, Math.min(1, c))));
            }
            image.setRGB(p % SIZE_PX, p / SIZE_PX, packed);
        }
        return image;
    }

    /** CIEDE2000 as a ramp from black through red and yellow to white at {@link #ERROR_WHITE}. */
    static BufferedImage errorImage(double[] deltaE) {
        BufferedImage image = new BufferedImage(SIZE_PX, SIZE_PX, BufferedImage.TYPE_INT_RGB);
        for (int p = 0; p < deltaE.length; p++) {
            double t = Math.min(1, deltaE[p] / ERROR_WHITE);
            int r = (int) Math.round(255 * Math.min(1, 3 * t));
            int g = (int) Math.round(255 * Math.max(0, Math.min(1, 3 * t - 1)));
            int b = (int) Math.round(255 * Math.max(0, Math.min(1, 3 * t - 2)));
            image.setRGB(p % SIZE_PX, p / SIZE_PX, r << 16 | g << 8 | b);
        }
        return image;
    }

    private static ImageIcon icon(BufferedImage image) {
        return new ImageIcon(image.getScaledInstance(SHOWN_PX, SHOWN_PX, Image.SCALE_FAST));
    }

    void close() {
        diffract.util.BackgroundThreads.stop(worker);
    }
}
