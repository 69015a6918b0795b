package diffract.geometry;

import java.awt.image.BufferedImage;
import java.util.stream.IntStream;

/**
 * A {@link ScaleLattice} laid on a {@link SnakeMesh}: where each row of scales lies along the body, how large a
 * scale is in metres there, and the two textures the shaders read, both in the snake's UV layout and both meant to
 * be mip-mapped (the frame map as floats, so averages of normals stay meaningful).
 *
 * <p>Along the body a scale row's length follows the body's girth, l(v) proportional to max(0.3, r(v) / r_max),
 * so scales shrink towards the snout and the tail tip as on the animal; q(v), the scale-row coordinate, is the
 * integral of dv / l(v), scaled so that the rows from the snout to the vent number the species' ventral count.
 *
 * <p>The frame map holds per texel (RGBA) the visible scale's unit normal's components along the mesh's tangent and
 * bitangent (the third follows from unit length) and the scale's long axis in the tangent plane, expressed in the
 * mesh's tangent frame: for ridges along the body that frame is (along, around, out); for ridges around it
 * (around, -along, out) and the patch's x axis is the long axis turned by 90 degrees about the normal, which in
 * that frame has the same two components. So the shader needs no switch: it rebuilds (T', B', N') from the texel.
 */
public final class ScaledSkin {
    /** Samples of q(v) and the sizes along the body. */
    private static final int PROFILE_SAMPLES = 4096;

    private final ScaleLattice lattice;
    private final SnakeMesh.RidgeDirection ridges;
    private final double[] q = new double[PROFILE_SAMPLES + 1];
    private final double[] rowLengthM = new double[PROFILE_SAMPLES + 1];
    private final double[] circumferenceM = new double[PROFILE_SAMPLES + 1];

    public ScaledSkin(ScaleLattice lattice, SnakeMesh.Profile profile, SnakeMesh.RidgeDirection ridges) {
        this.lattice = lattice;
        this.ridges = ridges;
        double[] v = profile.v();
        double[] halfWidth = profile.halfWidthM();
        double maxHalfWidth = 0;
        for (double r : halfWidth) {
            maxHalfWidth = Math.max(maxHalfWidth, r);
        }
        double[] spacing = new double[PROFILE_SAMPLES + 1];
        for (int s = 0; s <= PROFILE_SAMPLES; s++) {
            double vs = (double) s / PROFILE_SAMPLES;
            int i = ringBelow(v, vs);
            double r;
            double circumference;
            if (i < 0) {
                r = halfWidth[0] * vs / v[0];
                circumference = profile.circumferenceM(0) * vs / v[0];
            } else if (i >= v.length - 1) {
                double f = (1 - vs) / (1 - v[v.length - 1]);
                r = halfWidth[v.length - 1] * f;
                circumference = profile.circumferenceM(v.length - 1) * f;
            } else {
                double f = (vs - v[i]) / (v[i + 1] - v[i]);
                r = halfWidth[i] + f * (halfWidth[i + 1] - halfWidth[i]);
                circumference = profile.circumferenceM(i) + f * (profile.circumferenceM(i + 1) - profile.circumferenceM(i));
            }
            spacing[s] = Math.max(0.3, r / maxHalfWidth);
            circumferenceM[s] = Math.max(circumference, 1e-6);
        }
        // q = integral of dv / spacing (trapezoid), then scaled to the ventral count at the vent
        double[] raw = new double[PROFILE_SAMPLES + 1];
        for (int s = 1; s <= PROFILE_SAMPLES; s++) {
            raw[s] = raw[s - 1] + 0.5 * (1 / spacing[s - 1] + 1 / spacing[s]) / PROFILE_SAMPLES;
        }
        double ventQ = interpolate(raw, profile.ventV());
        double scale = lattice.parameters().ventralScales() / ventQ;
        for (int s = 0; s <= PROFILE_SAMPLES; s++) {
            q[s] = raw[s] * scale;
            rowLengthM[s] = spacing[s] / scale * profile.lengthAlongM();
        }
    }

    private static int ringBelow(double[] v, double vs) {
        if (vs < v[0]) {
            return -1;
        }
        int lo = 0;
        int hi = v.length - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) / 2;
            if (v[mid] <= vs) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }

    private static double interpolate(double[] table, double v) {
        double f = Math.max(0, Math.min(1, v)) * PROFILE_SAMPLES;
        int s = Math.min(PROFILE_SAMPLES - 1, (int) Math.floor(f));
        return table[s] + (f - s) * (table[s + 1] - table[s]);
    }

    public ScaleLattice lattice() {
        return lattice;
    }

    /** The scale-row coordinate at texture coordinate v. */
    public double q(double v) {
        return interpolate(q, v);
    }

    /** Length of one scale row along the body at v, metres. */
    public double rowLengthM(double v) {
        return interpolate(rowLengthM, v);
    }

    /** Width of one dorsal row around the body at v, metres. */
    public double rowWidthM(double v) {
        ScaleLattice.Parameters p = lattice.parameters();
        return interpolate(circumferenceM, v) * (1 - p.ventralFraction()) / p.dorsalRows();
    }

    /** Half-width of the ventral band at v, metres. */
    public double ventralHalfWidthM(double v) {
        return interpolate(circumferenceM, v) * lattice.parameters().ventralFraction() / 2;
    }

    /** The scale visible at texture coordinates (u, v). */
    public ScaleLattice.Hit visible(double u, double v) {
        return lattice.visible(u, q(v));
    }

    /**
     * The frame at (u, v) in the mesh's tangent frame: {nT, nB, nN, axisT, axisB} (see the class comment).
     */
    public double[] frameAt(double u, double v) {
        ScaleLattice.Hit hit = visible(u, v);
        double[] f = lattice.frame(hit, hit.ventral() ? ventralHalfWidthM(v) : rowWidthM(v), rowLengthM(v));
        if (ridges == SnakeMesh.RidgeDirection.ALONG_BODY) {
            return f;
        }
        // tangent = around, bitangent = -along; the patch's x axis (the long axis turned by 90 degrees) keeps (c, s)
        return new double[] {f[1], -f[0], f[2], f[3], f[4]};
    }

    /**
     * The frame map: {@code widthPx x heightPx} texels, RGBA floats per texel (see the class comment), row r at
     * v = (r + 0.5) / heightPx (the first row is texture row 0, the snout end), column c at u = (c + 0.5) / widthPx.
     */
    public float[] frameMap(int widthPx, int heightPx) {
        checkSize(widthPx, heightPx);
        float[] rgba = new float[4 * widthPx * heightPx];
        IntStream.range(0, heightPx).parallel().forEach(row -> {
            double v = (row + 0.5) / heightPx;
            for (int c = 0; c < widthPx; c++) {
                double[] f = frameAt((c + 0.5) / widthPx, v);
                int k = 4 * (row * widthPx + c);
                rgba[k] = (float) f[0];
                rgba[k + 1] = (float) f[1];
                rgba[k + 2] = (float) f[3];
                rgba[k + 3] = (float) f[4];
            }
        });
        return rgba;
    }

    /**
     * The species' pigmentation as a display-sRGB image in the layout of {@link PigmentationTexture} (image row 0
     * at v = 1, the tail tip, since textures are uploaded bottom row first).
     */
    public BufferedImage pigmentImage(SkinPattern pattern, int widthPx, int heightPx) {
        checkSize(widthPx, heightPx);
        BufferedImage image = new BufferedImage(widthPx, heightPx, BufferedImage.TYPE_INT_RGB);
        int[] pixels = new int[widthPx * heightPx];
        IntStream.range(0, heightPx).parallel().forEach(y -> {
            double v = 1 - (y + 0.5) / heightPx;
            for (int x = 0; x < widthPx; x++) {
                pixels[y * widthPx + x] = pattern.srgb(visible((x + 0.5) / widthPx, v));
            }
        });
        image.setRGB(0, 0, widthPx, heightPx, pixels, 0, widthPx);
        return image;
    }

    private static void checkSize(int widthPx, int heightPx) {
        if (widthPx < 8 || heightPx < 8 || (long) widthPx * heightPx > 32L * 1024 * 1024) {
            throw new IllegalArgumentException("scale map size must be 8..32 Mtexel, got " + widthPx + " x " + heightPx);
        }
    }
}
