package diffract.optics.maps;

import diffract.optics.BrdfMap;
import diffract.optics.patches.Direction;

/**
 * Picks a display exposure for a BRDF map (pixel convention of {@link BrdfMap}): the brightest diffracted pixel, ignoring the specular highlight (the
 * pixels within 3 pixels of the mirror direction), is mapped to 1. Diffraction orders are typically 10-1000 times
 * dimmer than the specular peak, so exposure 1 shows mostly black; this keeps their colours visible.
 */
public final class AutoExposure {
    public static final int SPECULAR_RADIUS_PX = 3;

    private AutoExposure() {
    }

    /**
     * @param luminance  one value per pixel (Y, or the relative BRDF)
     * @param specularX  tangent-frame x of the mirror direction, -sin(theta_i) cos(phi_i)
     * @param specularY  tangent-frame y of the mirror direction
     */
    public static double of(float[] luminance, int size, double specularX, double specularY) {
        double max = brightestDiffracted(luminance, size, specularX, specularY);
        return max > 0 && Double.isFinite(max) ? 1.0 / max : 1.0;
    }

    /** {@link #of} for a map of XYZ triples ({@link BrdfMap}): its Y, with the mirror direction of {@code wi}. */
    public static double ofXyz(float[] xyz, Direction wi, int size) {
        float[] y = new float[size * size];
        for (int p = 0; p < y.length; p++) {
            y[p] = xyz[3 * p + 1];
        }
        return of(y, size, -wi.x(), -wi.y());
    }

    /** The largest value outside the specular highlight (0 when there is none). */
    public static double brightestDiffracted(float[] luminance, int size, double specularX, double specularY) {
        double specularColumn = (specularX + 1) * size / 2 - 0.5;
        double specularRow = (1 - specularY) * size / 2 - 0.5;
        double max = 0;
        for (int j = 0; j < size; j++) {
            for (int i = 0; i < size; i++) {
                if (Math.hypot(i - specularColumn, j - specularRow) <= SPECULAR_RADIUS_PX) {
                    continue;
                }
                max = Math.max(max, luminance[j * size + i]);
            }
        }
        return max;
    }
}
