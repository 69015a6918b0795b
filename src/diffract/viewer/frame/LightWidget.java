package diffract.viewer.frame;

import diffract.scene.LightDirection;
import diffract.viewer.ViewerState;
import diffract.viewer.ViewerWindow;

import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JPanel;
import java.awt.BasicStroke;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * The light on its hemisphere, as a BRDF explorer shows it: the upper hemisphere seen from above (orthographic:
 * a direction at (theta, phi) sits at sin theta (cos phi, sin phi) of the disc, phi from x to the right towards y up),
 * the key light as a dot with its angular size as a ring, and the direction towards the camera marked. Dragging on it
 * puts the light under the pointer, through the view's input queue as the keys do.
 */
public final class LightWidget extends JComponent {
    static final int SIZE_PX = 180;
    /** The strip under the disc that names the light's angles. */
    static final int LABEL_PX = 14;
    private final Supplier<ViewerWindow> view;
    private volatile ViewerState state;

    LightWidget(Supplier<ViewerWindow> view) {
        this.view = view;
        setPreferredSize(new Dimension(SIZE_PX, SIZE_PX));
        setMinimumSize(new Dimension(SIZE_PX, SIZE_PX));
        setToolTipText("drag the light on the hemisphere (seen from above); the square is the camera");
        MouseAdapter drag = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                moveTo(e.getX(), e.getY());
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                moveTo(e.getX(), e.getY());
            }
        };
        addMouseListener(drag);
        addMouseMotionListener(drag);
    }

    JPanel titled() {
        JPanel p = new JPanel(new BorderLayout());
        p.setBorder(BorderFactory.createTitledBorder("Light"));
        p.add(this, BorderLayout.CENTER);
        p.setMaximumSize(new Dimension(SIZE_PX + 20, SIZE_PX + 30));
        return p;
    }

    void refresh(ViewerState s) {
        if (!s.equals(state)) {
            state = s;
            repaint();
        }
    }

    /** The disc's centre and radius in this component's pixels. */
    private double[] disc() {
        double r = Math.min(getWidth(), getHeight() - LABEL_PX) / 2.0 - 6;
        return new double[] {getWidth() / 2.0, (getHeight() - LABEL_PX) / 2.0, Math.max(r, 1)};
    }

    /** The light direction under the pixel (x, y): (theta_i, phi_i) in degrees, theta at most the light's limit. */
    double[] directionAt(int x, int y) {
        double[] d = disc();
        double u = (x - d[0]) / d[2];
        double v = -(y - d[1]) / d[2];
        double s = Math.min(1, Math.hypot(u, v));
        double theta = Math.min(LightDirection.MAX_THETA_DEG, Math.toDegrees(Math.asin(s)));
        double phi = Math.toDegrees(Math.atan2(v, u));
        return new double[] {theta, phi < 0 ? phi + 360 : phi};
    }

    /** The pixel of direction (theta, phi) in degrees. */
    int[] pixelOf(double thetaDeg, double phiDeg) {
        double[] d = disc();
        double s = Math.sin(Math.toRadians(thetaDeg));
        double phi = Math.toRadians(phiDeg);
        return new int[] {(int) Math.round(d[0] + d[2] * s * Math.cos(phi)),
                (int) Math.round(d[1] - d[2] * s * Math.sin(phi))};
    }

    private void moveTo(int x, int y) {
        ViewerWindow v = view.get();
        if (v == null) {
            return;
        }
        double[] dir = directionAt(x, y);
        v.controller().queue(c -> c.setLight(dir[0], dir[1]));
    }

    @Override
    protected void paintComponent(Graphics g0) {
        Graphics2D g = (Graphics2D) g0.create();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        double[] d = disc();
        int cx = (int) Math.round(d[0]);
        int cy = (int) Math.round(d[1]);
        int r = (int) Math.round(d[2]);
        g.setColor(new Color(30, 30, 36));
        g.fillOval(cx - r, cy - r, 2 * r, 2 * r);
        g.setColor(new Color(90, 90, 100));
        for (int deg : new int[] {30, 60}) {
            int rr = (int) Math.round(r * Math.sin(Math.toRadians(deg)));
            g.drawOval(cx - rr, cy - rr, 2 * rr, 2 * rr);
        }
        g.drawLine(cx - r, cy, cx + r, cy);
        g.drawLine(cx, cy - r, cx, cy + r);
        g.setColor(new Color(160, 160, 170));
        g.drawOval(cx - r, cy - r, 2 * r, 2 * r);
        g.drawString("x", cx + r - 8, cy - 3);
        g.drawString("y", cx + 3, cy - r + 12);
        ViewerState s = state;
        if (s != null) {
            double[] eye = s.view().camera().eye();
            double len = Math.sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
            double theta = Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, eye[2] / len))));
            double phi = Math.toDegrees(Math.atan2(eye[1], eye[0]));
            int[] camera = pixelOf(Math.min(90, theta), phi);
            g.setColor(new Color(90, 170, 255));
            if (theta <= 90) {
                g.fillRect(camera[0] - 4, camera[1] - 4, 9, 9);
            } else {
                g.drawRect(camera[0] - 4, camera[1] - 4, 9, 9); // below the horizon: at the rim, hollow
            }
            LightDirection light = s.view().light();
            int[] at = pixelOf(light.thetaDeg(), light.phiDeg());
            double sizeDeg = s.settings().illumination().light().angularDiameterDeg();
            int ring = (int) Math.round(r * Math.sin(Math.toRadians(sizeDeg / 2)));
            g.setColor(new Color(255, 210, 60));
            g.fillOval(at[0] - 5, at[1] - 5, 11, 11);
            if (ring > 5) {
                g.setStroke(new BasicStroke(1.5f));
                g.drawOval(at[0] - ring, at[1] - ring, 2 * ring, 2 * ring);
            }
            g.setColor(getForeground());
            g.drawString(String.format(Locale.ROOT, "light %.0f, %.0f; camera %.0f, %.0f", light.thetaDeg(),
                    light.phiDeg(), theta, phi < 0 ? phi + 360 : phi), 2, getHeight() - 3);
        }
        g.dispose();
    }
}
