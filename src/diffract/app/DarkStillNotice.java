package diffract.app;

import diffract.pipeline.PatchPeriod;
import diffract.scene.Scene;
import diffract.scene.SceneSetup;

import java.util.Locale;
import java.util.Optional;

/**
 * Says when a still's structural colour comes out black, or nearly so, and what would show it, as a BRDF map's
 * notice does ({@link DarkMapNotice}): a picture that is silently black looks like a bug. Read from the
 * {@link StructuralProbe} of the picture (its structural colour alone). Three cases:
 * <ul>
 *   <li>no pixel of the shape sends diffracted light to the camera: the orders leave where the camera does not look.
 *   For a plane with a patch of a clear period d (a grating), the light that sends the first order at 550 nm to the
 *   centre of the view (sin theta_i along the period = lambda / d less the view's own tilt) is named; otherwise
 *   another light, a wider one or the BRDF map of the light;</li>
 *   <li>the light is there but the exposure hides it: {@code --exposure auto} maps it to white;</li>
 *   <li>it is dim: a note, with the same remedy.</li>
 * </ul>
 */
final class DarkStillNotice {
    /**
     * Bright pixels (the 99th percentile of the lit ones) exposed below this are black in the PNG: sRGB below 7 of 255.
     */
    static final double BLACK_Y = 2e-3;
    /** An exposure this many times the scene's to show the picture means the orders miss the camera. */
    static final double FAINT_FACTOR = 100;
    /** The wavelength whose first order the suggestion sends to the camera (the eye's most sensitive). */
    static final double GREEN_NM = 550;

    private DarkStillNotice() {
    }

    /** Why the picture is dark: what an exposure can fix ({@link #exposureHides}) and what it cannot. */
    enum Kind { NOT_IN_PICTURE, NO_LIGHT, BLACK, DIM }

    /** What to say: a warning (nothing to see) or a note (dim). */
    record Notice(Kind kind, boolean warning, String text) {
        /** Whether another exposure shows it (a linear file, which is not exposed, has nothing to fix then). */
        boolean exposureHides() {
            return kind == Kind.BLACK || kind == Kind.DIM;
        }
    }

    /**
     * @param probe    the picture's structural colour alone
     * @param setup    the scene drawn (its exposure, shape, camera, light and patch)
     * @param shapeKind what the scene shows, or null for a BRDF map
     */
    static Optional<Notice> check(StructuralProbe probe, SceneSetup setup, Scene.ShapeKind shapeKind) {
        String what = shapeKind == null ? "map" : shapeKind.sceneName();
        double exposure = setup.exposure();
        if (probe.shapePixels() == 0) {
            return Optional.of(new Notice(Kind.NOT_IN_PICTURE, true, "the " + what + " is not in the picture: the camera "
                    + "looks past it (--azimuth, --elevation, --distance, or the scene's camera)"));
        }
        if (!(probe.brightestY() > DarkMapNotice.EMPTY_Y)) {
            return Optional.of(new Notice(Kind.NO_LIGHT, true, "the picture shows no structural colour: no pixel of "
                    + "the " + what + " sends diffracted light to the camera" + remedy(setup, shapeKind)));
        }
        if (probe.brightY() * exposure < BLACK_Y) {
            return Optional.of(new Notice(Kind.BLACK, true, String.format(Locale.ROOT, "the structural colour is "
                    + "black at exposure %s: its bright pixels show %.2g of white; --exposure auto maps them to white "
                    + "(exposure %.3g)%s", number(exposure), probe.brightY() * exposure, probe.autoExposure(1),
                    probe.autoExposure(1) > FAINT_FACTOR * exposure ? "; light that faint is the orders' tails, not "
                    + "the orders" + remedy(setup, shapeKind) : "")));
        }
        if (probe.brightY() * exposure < DarkMapNotice.DIM_Y) {
            return Optional.of(new Notice(Kind.DIM, false, String.format(Locale.ROOT, "the structural colour is "
                    + "dim at exposure %s: its bright pixels show %.2g of white; --exposure auto maps them to white "
                    + "(exposure %.3g)", number(exposure), probe.brightY() * exposure, probe.autoExposure(1))));
        }
        return Optional.empty();
    }

    /** What would send the patch's colour to the camera. */
    static String remedy(SceneSetup setup, Scene.ShapeKind shapeKind) {
        String general = "; another light (--theta-i, --phi-i), a wider one (--light-size-deg) or a shorter "
                + "--coherence-length spreads the orders, and --brdf-map shows where they go under this light";
        Optional<PatchPeriod> period = PatchPeriod.of(setup.patch());
        if (shapeKind != Scene.ShapeKind.PLANE || period.isEmpty()) {
            return general;
        }
        Optional<double[]> light = firstOrderLight(period.get(), setup.camera().eye(), new double[] {
                setup.camera().targetX(), setup.camera().targetY(), setup.camera().targetZ()});
        if (light.isEmpty()) {
            return String.format(Locale.ROOT, ": the patch's period, %.3g um, is below the wavelength, so no "
                    + "order leaves it" + general, period.get().periodUm());
        }
        return String.format(Locale.ROOT, ": the patch's period, %.3g um at %.0f degrees, sends its first order at "
                + "%.0f nm to the centre of the view under --theta-i %.1f --phi-i %.0f%s", period.get().periodUm(),
                period.get().azimuthDeg(), GREEN_NM, light.get()[0], light.get()[1], general);
    }

    /**
     * The light (theta_i, phi_i in degrees, the viewer's convention: from z, phi from x towards y) that sends the first
     * order at {@link #GREEN_NM} of a plane in the xy plane towards the camera at its look-at point: omega_i.xy =
     * -omega_r.xy - m lambda f for the order m = +-1 that needs the smaller theta_i; empty when neither is above the
     * horizon.
     */
    static Optional<double[]> firstOrderLight(PatchPeriod period, double[] eye, double[] target) {
        double dx = eye[0] - target[0];
        double dy = eye[1] - target[1];
        double dz = eye[2] - target[2];
        double norm = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double[] wr = {dx / norm, dy / norm};
        double lambdaFrequency = GREEN_NM * 1e-3 / period.periodUm();
        double az = Math.toRadians(period.azimuthDeg());
        double[] best = null;
        for (int m : new int[] {1, -1}) {
            double x = -wr[0] - m * lambdaFrequency * Math.cos(az);
            double y = -wr[1] - m * lambdaFrequency * Math.sin(az);
            double s = Math.hypot(x, y);
            if (s < 1 && (best == null || s < best[2])) {
                best = new double[] {x, y, s};
            }
        }
        if (best == null) {
            return Optional.empty();
        }
        double theta = Math.toDegrees(Math.asin(best[2]));
        double phi = Math.toDegrees(Math.atan2(best[1], best[0]));
        return Optional.of(new double[] {theta, (phi % 360 + 360) % 360});
    }

    private static String number(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e9 ? Long.toString((long) value)
                : String.format(Locale.ROOT, "%.4g", value);
    }
}
