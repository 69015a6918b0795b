package diffract.viewer.frame;

import diffract.optics.BrdfSettings;
import diffract.optics.settings.LightProfile;
import diffract.optics.Methods;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.TaylorSettings;
import diffract.optics.Variant;
import diffract.scene.DisplayMode;
import diffract.scene.Scene;
import diffract.viewer.ViewerController;
import diffract.viewer.ViewerState;
import diffract.viewer.ViewerWindow;

import javax.swing.BorderFactory;
import javax.swing.DefaultListCellRenderer;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JSlider;
import java.awt.Color;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * The settings that matter, as controls (the BRDF explorers' parameter panel): method, N, wavelength step, coherence
 * length, light size and profile, window radius, exposure, pigment, shape, the BRDF-map mode and the A/B split. Each
 * change goes into the view's input queue as a key would ({@link ViewerController}), so it is applied between the
 * refinement's tiles and redrawn through the same refinement. A control the method or the patch refuses is disabled,
 * with the reason under it: the method's own answer ({@link Variant#unsweptSettings}, {@link Variant#filtersLight},
 * {@link Variant#patchRefusal}). The controls are read back from the state on the frame's timer, so the keys move them
 * too. None takes the keyboard's focus, which stays with the view (its keys).
 */
public final class SettingsPanel extends JPanel {
    /** The coherence lengths offered (um), the thesis' 65 among them. */
    static final double[] COHERENCE_UM = {5, 10, 20, 32.5, 65, 130, 260};
    /** The light sizes offered (degrees): a point, the sun, and the soft lights of the staged scenes. */
    static final double[] LIGHT_DEG = {0, 0.53, 1, 2, 5, 10, 15, 20};
    /** The wavelength steps offered (nm), those of the [ and ] keys. */
    static final double[] LAMBDA_STEPS_NM = {1, 2, 5, 10, 20, 40};
    /** The window radii offered; "auto" is the automatic radius. */
    static final String[] WINDOW = {"auto", "0", "1", "2", "3", "4", "6", "8"};
    /** The exposure slider's steps per stop (a factor of 2). */
    static final int STEPS_PER_STOP = 2;

    private final Supplier<ViewerWindow> view;
    private final Consumer<Scene.ShapeKind> shapeChange;
    private final Map<String, Row> rows = new LinkedHashMap<>();
    private final JComboBox<String> method = combo(methodLabels());
    private final JSlider terms = slider(0, TaylorSettings.MAX_HIGHEST_ORDER);
    private final JComboBox<String> lambdaStep = combo(labels(LAMBDA_STEPS_NM, " nm"));
    private final JComboBox<String> coherence = combo(labels(COHERENCE_UM, " um"));
    private final JComboBox<String> lightSize = combo(labels(LIGHT_DEG, " deg"));
    private final JComboBox<String> profile = combo(Arrays.stream(LightProfile.values()).map(LightProfile::label)
            .toArray(String[]::new));
    private final JComboBox<String> window = combo(WINDOW);
    private final JSlider exposure = slider(-8 * STEPS_PER_STOP, 24 * STEPS_PER_STOP);
    private final JCheckBox pigment = check("pigment");
    private final JComboBox<String> shape = combo(new String[] {"sphere", "plane", "cylinder", "snake"});
    private final JCheckBox brdfMap = check("BRDF map");
    private final JCheckBox split = check("A/B split");
    private final JComboBox<String> splitMethod = combo(methodLabels());
    private final JSlider divider = slider(0, 100);
    private boolean updating;
    private ViewerState shown;
    /**
     * The state when the user last changed a control, until the view applied the change (or {@link #QUIET_MS}
     * passed): the controls are not set back from a state that has not seen the change yet.
     */
    private ViewerState beforeChange;
    private long changedAtMillis;
    static final long QUIET_MS = 2000;

    /** A control, its label (which shows a slider's value), and the reason it is disabled (empty when enabled). */
    private record Row(JComponent control, JLabel value, JLabel reason) {
    }

    SettingsPanel(Supplier<ViewerWindow> view, Consumer<Scene.ShapeKind> shapeChange) {
        this.view = view;
        this.shapeChange = shapeChange;
        setLayout(new GridBagLayout());
        setBorder(BorderFactory.createTitledBorder("Settings"));
        add("method", method);
        add("N", terms);
        add("wavelength step", lambdaStep);
        add("coherence length", coherence);
        add("light size", lightSize);
        add("light profile", profile);
        add("window R", window);
        add("exposure", exposure);
        add("pigment", pigment);
        add("shape", shape);
        add("mode", brdfMap);
        add("A/B", split);
        add("B method", splitMethod);
        add("divider", divider);
        method.setRenderer(new MethodRenderer());
        splitMethod.setRenderer(new MethodRenderer());
        listen();
        setMaximumSize(new Dimension(ViewerFrame.SIDE_WIDTH_PX, Integer.MAX_VALUE));
    }

    private void add(String name, JComponent control) {
        GridBagConstraints c = new GridBagConstraints();
        int row = 2 * rows.size();
        c.gridy = row;
        c.gridx = 0;
        c.anchor = GridBagConstraints.WEST;
        c.insets = new Insets(2, 2, 0, 4);
        JLabel label = new JLabel(name);
        add(label, c);
        c.gridx = 1;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.weightx = 1;
        add(control, c);
        JLabel reason = new JLabel("");
        reason.setFont(reason.getFont().deriveFont(Font.PLAIN, 10f));
        reason.setForeground(new Color(150, 70, 40));
        reason.setVisible(false);
        c.gridy = row + 1;
        c.gridx = 0;
        c.gridwidth = 2;
        c.insets = new Insets(0, 6, 2, 2);
        add(reason, c);
        rows.put(name, new Row(control, label, reason));
    }

    private static JComboBox<String> combo(String[] items) {
        JComboBox<String> c = new JComboBox<>(items);
        c.setFocusable(false); // the keys stay with the view
        c.setPrototypeDisplayValue("coherence");
        return c;
    }

    private static JSlider slider(int min, int max) {
        JSlider s = new JSlider(min, max, min);
        s.setFocusable(false);
        s.setPreferredSize(new Dimension(100, s.getPreferredSize().height));
        return s;
    }

    private static JCheckBox check(String text) {
        JCheckBox c = new JCheckBox(text);
        c.setFocusable(false);
        return c;
    }

    private static String[] labels(double[] values, String unit) {
        return Arrays.stream(values).mapToObj(v -> number(v) + unit).toArray(String[]::new);
    }

    static String number(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : String.format(Locale.ROOT, "%.3g", v);
    }

    /** The methods the GPU draws, by label. */
    static String[] methodLabels() {
        return Arrays.stream(Variant.values()).filter(Variant::runsOnGpu).map(Variant::label).toArray(String[]::new);
    }

    // ---- from the controls to the view

    private void listen() {
        method.addActionListener(e -> apply(() -> selectedVariant(method).ifPresent(v -> queue(c -> c.selectVariant(v)))));
        terms.addChangeListener(e -> {
            if (!terms.getValueIsAdjusting()) {
                int n = terms.getValue();
                apply(() -> queue(c -> c.setTaylorOrder(n)));
            }
        });
        lambdaStep.addActionListener(e -> apply(() -> {
            double nm = LAMBDA_STEPS_NM[lambdaStep.getSelectedIndex()];
            queue(c -> c.setLambdaStep(nm));
        }));
        coherence.addActionListener(e -> apply(() -> {
            double um = COHERENCE_UM[coherence.getSelectedIndex()];
            queue(c -> c.setCoherenceLength(um));
        }));
        lightSize.addActionListener(e -> apply(() -> {
            double deg = LIGHT_DEG[lightSize.getSelectedIndex()];
            queue(c -> c.setLightSize(deg));
        }));
        profile.addActionListener(e -> apply(() -> {
            LightProfile p = LightProfile.values()[profile.getSelectedIndex()];
            queue(c -> c.setLightProfile(p));
        }));
        window.addActionListener(e -> apply(() -> {
            String r = WINDOW[window.getSelectedIndex()];
            Integer radius = r.equals("auto") ? null : Integer.valueOf(r);
            queue(c -> c.setWindowRadius(radius));
        }));
        exposure.addChangeListener(e -> {
            if (!exposure.getValueIsAdjusting()) {
                double value = Math.pow(2, exposure.getValue() / (double) STEPS_PER_STOP);
                apply(() -> {
                    ViewerState s = shown;
                    // only a step away from the state's exposure moves it (the slider rounds to half stops)
                    if (s == null || Math.abs(sliderOf(s.view().exposure()) - exposure.getValue()) > 0) {
                        queue(c -> c.setExposure(value));
                    }
                });
            }
        });
        pigment.addActionListener(e -> apply(() -> {
            boolean on = pigment.isSelected();
            queue(c -> c.setPigmentation(on));
        }));
        shape.addActionListener(e -> apply(() -> {
            Scene.ShapeKind kind = Scene.ShapeKind.valueOf(((String) shape.getSelectedItem()).toUpperCase(Locale.ROOT));
            shapeChange.accept(kind);
        }));
        brdfMap.addActionListener(e -> apply(() -> {
            DisplayMode mode = brdfMap.isSelected() ? DisplayMode.BRDF_MAP : DisplayMode.SURFACE;
            queue(c -> c.setMode(mode));
        }));
        split.addActionListener(e -> apply(() -> {
            ViewerState s = live();
            if (s == null) {
                return;
            }
            if (!split.isSelected()) {
                queue(c -> c.setSplit(null));
                return;
            }
            Variant b = selectedVariant(splitMethod).orElse(otherThan(s.settings().variant()));
            BrdfSettings other = s.settings().with(x -> x.variant(b));
            queue(c -> c.setSplit(new ViewerState.Split(other, divider.getValue() / 100.0)));
        }));
        splitMethod.addActionListener(e -> apply(() -> {
            ViewerState s = live();
            if (s == null || s.view().split() == null) {
                return;
            }
            selectedVariant(splitMethod).ifPresent(b -> {
                BrdfSettings other = s.view().split().other().with(x -> x.variant(b));
                queue(c -> c.setSplit(s.view().split().withOther(other)));
            });
        }));
        divider.addChangeListener(e -> {
            if (!divider.getValueIsAdjusting()) {
                double d = divider.getValue() / 100.0;
                apply(() -> queue(c -> c.setSplitDivider(d)));
            }
        });
    }

    /** The view's state now (the controls may show an older one). */
    private ViewerState live() {
        ViewerWindow v = view.get();
        return v != null ? v.model().state() : shown;
    }

    /** Runs a change unless the controls are being set from the state. */
    private void apply(Runnable change) {
        if (!updating) {
            change.run();
        }
    }

    private void queue(Consumer<ViewerController> action) {
        ViewerWindow v = view.get();
        if (v != null) {
            beforeChange = v.model().state();
            changedAtMillis = System.currentTimeMillis();
            v.controller().queue(action);
        }
    }

    /** The method selected in a combo, unless the patch refuses it (then its row says why). */
    private Optional<Variant> selectedVariant(JComboBox<String> combo) {
        Variant v = Variant.parse((String) combo.getSelectedItem());
        Optional<String> refusal = refusal(v);
        if (refusal.isPresent()) {
            Row row = combo == method ? rows.get("method") : rows.get("B method");
            showReason(row, refusal.get());
            return Optional.empty();
        }
        return Optional.of(v);
    }

    private static Variant otherThan(Variant a) {
        Variant reference = Methods.Role.FILTERING.method();
        return a.equals(reference) ? Methods.Role.TABLE.method() : reference;
    }

    /** Why the view's patch refuses method {@code v} with the current settings; empty if it takes it. */
    private Optional<String> refusal(Variant v) {
        ViewerWindow w = view.get();
        ViewerState s = live();
        if (w == null || s == null) {
            return Optional.empty();
        }
        var patch = w.model().setup().patch();
        return v.patchRefusal(s.settings().with(b -> b.drawnBy(v)), patch.widthUm(), patch.heightExtentUm());
    }

    // ---- from the view to the controls

    void refresh(ViewerState s, Scene scene, boolean shapeChangeable) {
        if (s.equals(shown) || s.equals(beforeChange) && System.currentTimeMillis() - changedAtMillis < QUIET_MS) {
            return;
        }
        beforeChange = null;
        shown = s;
        updating = true;
        try {
            BrdfSettings b = s.settings();
            Variant v = b.variant();
            method.setSelectedItem(v.label());
            terms.setValue(b.taylor().highestOrder());
            rows.get("N").value().setText("N = " + b.taylor().highestOrder());
            select(lambdaStep, LAMBDA_STEPS_NM, b.spectral().lambdaStepNm());
            select(coherence, COHERENCE_UM, 4 * b.illumination().sigmaSpatialUm());
            double size = b.illumination().light().angularDiameterDeg();
            select(lightSize, LIGHT_DEG, size);
            profile.setSelectedItem(b.illumination().light().profile().label());
            window.setSelectedItem(b.window().automatic() ? "auto" : Integer.toString(b.window().radius()));
            exposure.setValue(sliderOf(s.view().exposure()));
            rows.get("exposure").value().setText(String.format(Locale.ROOT, "exposure %.3g", s.view().exposure()));
            pigment.setSelected(s.view().pigmentationOn());
            brdfMap.setSelected(s.view().mode() == DisplayMode.BRDF_MAP);
            shape.setSelectedItem(scene.shape().kind().sceneName());
            split.setSelected(s.view().split() != null);
            if (s.view().split() != null) {
                splitMethod.setSelectedItem(s.view().split().other().variant().label());
                divider.setValue((int) Math.round(100 * s.view().split().divider()));
            }
            enable("wavelength step", !v.unsweptSettings().contains(Quantity.LAMBDA_STEP),
                    v.label() + " does not step through the wavelengths (it integrates them its own way)");
            enable("window R", !v.unsweptSettings().contains(Quantity.WINDOW_RADIUS),
                    v.label() + " sums no window of texels");
            enable("light size", v.filtersLight(), v.label() + " samples the light at its centre: a point light ("
                    + Methods.listed(x -> x.filtersLight() && x.runsOnGpu(), "and") + " take its size)");
            enable("light profile", v.filtersLight() && size > 0, size > 0 ? v.label() + " draws a point light"
                    : "a point light has no profile");
            enable("pigment", view.get() != null && view.get().model().pigmentationImage().isPresent(),
                    "the scene has no pigmentation image");
            enable("shape", shapeChangeable && scene.source() == null, scene.source() != null
                    ? "the scene file " + scene.source().getFileName() + " says its shape" : "fixed here");
            enable("B method", s.view().split() != null, "switch the A/B split on");
            enable("divider", s.view().split() != null, "switch the A/B split on (or drag it in the view)");
            Optional<String> refused = refusal(v);
            showReason(rows.get("method"), refused.orElse(""));
        } finally {
            updating = false;
        }
    }

    private void enable(String name, boolean enabled, String reason) {
        Row row = rows.get(name);
        row.control().setEnabled(enabled);
        showReason(row, enabled ? "" : reason);
    }

    private static void showReason(Row row, String reason) {
        row.reason().setText(reason.isEmpty() ? "" : "<html><body style='width:230px'>" + reason + "</body></html>");
        row.reason().setVisible(!reason.isEmpty());
        row.control().setToolTipText(reason.isEmpty() ? null : reason);
    }

    private static void select(JComboBox<String> combo, double[] values, double value) {
        for (int i = 0; i < values.length; i++) {
            if (Math.abs(values[i] - value) < 1e-9 * Math.max(1, value)) {
                combo.setSelectedIndex(i);
                return;
            }
        }
        combo.setSelectedIndex(-1); // a value of the scene's own that the list does not offer
    }

    static int sliderOf(double exposure) {
        return (int) Math.round(Math.log(exposure) / Math.log(2) * STEPS_PER_STOP);
    }

    // ---- for tests: the controls by name, and why one is disabled

    /** The control of a row ("method", "N", "wavelength step", ...). */
    public JComponent control(String name) {
        Row row = rows.get(name);
        if (row == null) {
            throw new IllegalArgumentException("no control " + name + "; the controls: " + rows.keySet());
        }
        return row.control();
    }

    /** The names of the rows, top to bottom. */
    public List<String> names() {
        return List.copyOf(rows.keySet());
    }

    /** Why a row's control is disabled (empty when it is enabled). */
    public String reason(String name) {
        Row row = rows.get(name);
        return row.reason().isVisible() ? row.reason().getText().replaceAll("<[^>]*>", "") : "";
    }

    /** Greys the methods the patch refuses. */
    private final class MethodRenderer extends DefaultListCellRenderer {
        @Override
        public Component getListCellRendererComponent(JList<?> list, Object value, int index, boolean selected,
                                                      boolean focused) {
            Component c = super.getListCellRendererComponent(list, value, index, selected, focused);
            if (value instanceof String label && Arrays.asList(methodLabels()).contains(label)
                    && refusal(Variant.parse(label)).isPresent()) {
                c.setForeground(Color.GRAY);
            }
            return c;
        }
    }
}
