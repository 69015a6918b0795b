package diffract.viewer.frame;

import diffract.viewer.FrameStats;
import diffract.viewer.RefinementStatus;
import diffract.viewer.ViewerState;

import javax.swing.BorderFactory;
import javax.swing.BoxLayout;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.SwingUtilities;
import java.awt.Dimension;
import java.util.Locale;

/**
 * The frame's status bar: where the refinement stands (a progress bar of the pass under way), the background work
 * (the baked table's bake and spread, the Taylor terms' precompute: a progress bar each while it runs), the time of
 * the last full frame, and the latest notice or message. Read from the model's state on the frame's timer.
 */
public final class StatusBar extends JPanel {
    private final JLabel stage = new JLabel("starting");
    private final JProgressBar refinement = bar();
    private final JProgressBar work = bar();
    private final JLabel frameTime = new JLabel("");
    private final JLabel message = new JLabel("");
    private volatile String said;
    private volatile long saidUntilMillis = Long.MAX_VALUE;

    StatusBar() {
        setLayout(new BoxLayout(this, BoxLayout.X_AXIS));
        setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        add(stage);
        add(javax.swing.Box.createHorizontalStrut(6));
        add(refinement);
        add(javax.swing.Box.createHorizontalStrut(10));
        add(work);
        add(javax.swing.Box.createHorizontalStrut(10));
        add(frameTime);
        add(javax.swing.Box.createHorizontalStrut(10));
        add(message);
        add(javax.swing.Box.createHorizontalGlue());
        work.setVisible(false);
    }

    private static JProgressBar bar() {
        JProgressBar b = new JProgressBar(0, 100);
        b.setStringPainted(true);
        b.setPreferredSize(new Dimension(170, 18));
        b.setMaximumSize(new Dimension(220, 18));
        return b;
    }

    /** A message of the frame's own (opening a file...), until replaced; null clears it. */
    void say(String text) {
        said = text;
        saidUntilMillis = Long.MAX_VALUE;
    }

    /** A message for {@code millis}. */
    void sayFor(String text, long millis) {
        said = text;
        saidUntilMillis = System.currentTimeMillis() + millis;
    }

    void refresh(ViewerState state, RefinementStatus status, FrameStats stats, String busy) {
        stage.setText(stageText(status));
        refinement.setValue((int) Math.round(100 * (status.stage() == RefinementStatus.Stage.REFINED ? 1
                : status.fraction())));
        refinement.setString(status.stage() == RefinementStatus.Stage.REFINED ? "refined"
                : String.format(Locale.ROOT, "1/%d %d%%", status.divisor(), Math.round(100 * status.fraction())));
        String workText = null;
        int workPercent = 0;
        if (state.bake() != null) {
            workText = "table " + state.bake().percent() + "%";
            workPercent = state.bake().percent();
        } else if (state.precompute() != null) {
            workText = "terms N=" + state.precompute().targetOrder() + " " + state.precompute().percent() + "%";
            workPercent = state.precompute().percent();
        }
        work.setVisible(workText != null);
        if (workText != null) {
            work.setValue(workPercent);
            work.setString(workText);
        }
        frameTime.setText(stats.frameCount() > 0 ? String.format(Locale.ROOT, "%.0f ms/frame",
                stats.msPerFrame()) : "- ms/frame");
        long now = System.nanoTime();
        String text = said != null && System.currentTimeMillis() < saidUntilMillis ? said
                : state.notice() != null && state.notice().isShowingAt(now) ? state.notice().text()
                : busy != null ? busy : "";
        message.setText(text);
        message.setToolTipText(text.isEmpty() ? null : text);
    }

    private static String stageText(RefinementStatus s) {
        return switch (s.stage()) {
            case STARTING -> "starting";
            case PREVIEW -> "preview";
            case REFINING -> "refining";
            case WAITING_FOR_TABLE -> "preview (table baking)";
            case REFINED -> "refined";
            case FAILED -> "failed";
        };
    }

    /** What the bar shows now, as one line (tests read it). */
    public String text() {
        String[] out = new String[1];
        Runnable read = () -> out[0] = String.join(" | ", stage.getText(), refinement.getString(),
                work.isVisible() ? work.getString() : "", frameTime.getText(), message.getText());
        if (SwingUtilities.isEventDispatchThread()) {
            read.run();
        } else {
            ViewerFrame.onEdt(read);
        }
        return out[0];
    }
}
