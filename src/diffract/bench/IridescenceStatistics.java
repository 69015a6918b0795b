package diffract.bench;

import diffract.colour.Lab;
import diffract.colour.Srgb;
import diffract.colour.Xyz;

import java.util.ArrayDeque;
import java.util.Locale;

/**
 * How much of a picture shows the animal and how much of it flashes in structural colour, in scale-sized patches of
 * many hues: the numbers the photographs of Xenopeltis are compared with.
 *
 * <p>From a mask (where the animal is) and a picture of its structural colour alone (display sRGB in [0, 1]):
 * a pixel is saturated structural colour when it lies in the mask with CIELAB (D65) chroma C*ab >=
 * {@value #MIN_CHROMA} and lightness L* >= {@value #MIN_LIGHTNESS}; patches are 8-connected groups of such pixels
 * of at least {@value #MIN_PATCH_PX} pixels; hue bins split the hue angle h_ab into 12 bins of 30 degrees, a bin
 * counting when it holds at least 1 % of the saturated pixels.
 *
 * @param maskFraction       the animal's share of the frame
 * @param saturatedFraction  saturated structural colour's share of the frame
 * @param patches            separate patches
 * @param medianPatchPx      their median size, pixels
 * @param hueBins            hue bins (of 12) that count
 */
public record IridescenceStatistics(double maskFraction, double saturatedFraction, int patches, int medianPatchPx,
                                    int hueBins) {
    static final double MIN_CHROMA = 30;
    static final double MIN_LIGHTNESS = 20;
    static final int MIN_PATCH_PX = 3;

    /**
     * @param mask       one value per pixel, > 0.5 inside
     * @param structural display sRGB triples per pixel, rows top-down
     */
    public static IridescenceStatistics of(float[] mask, float[] structural, int width, int height) {
        int n = width * height;
        if (mask.length < n || structural.length != 3 * n) {
            throw new IllegalArgumentException("mask and picture must be " + width + " x " + height);
        }
        boolean[] saturated = new boolean[n];
        int inMask = 0;
        int count = 0;
        int[] bins = new int[12];
        Xyz white = Srgb.whiteXyz();
        for (int p = 0; p < n; p++) {
            if (!(mask[p] > 0.5)) {
                continue;
            }
            inMask++;
            double[] linear = {Srgb.decode(structural[3 * p]), Srgb.decode(structural[3 * p + 1]),
                Srgb.decode(structural[3 * p + 2])};
            Lab lab = Lab.fromXyz(Srgb.xyzFromLinear(linear), white);
            double chroma = Math.hypot(lab.a(), lab.b());
            if (chroma >= MIN_CHROMA && lab.l() >= MIN_LIGHTNESS) {
                saturated[p] = true;
                count++;
                double hue = Math.toDegrees(Math.atan2(lab.b(), lab.a()));
                bins[(int) Math.floor(((hue % 360) + 360) % 360 / 30) % 12]++;
            }
        }
        int hueBins = 0;
        for (int b : bins) {
            if (count > 0 && b >= 0.01 * count) {
                hueBins++;
            }
        }
        java.util.List<Integer> sizes = new java.util.ArrayList<>();
        boolean[] seen = new boolean[n];
        ArrayDeque<Integer> queue = new ArrayDeque<>();
        for (int p = 0; p < n; p++) {
            if (!saturated[p] || seen[p]) {
                continue;
            }
            int size = 0;
            seen[p] = true;
            queue.add(p);
            while (!queue.isEmpty()) {
                int q = queue.poll();
                size++;
                int x = q % width;
                int y = q / width;
                for (int dy = -1; dy <= 1; dy++) {
                    for (int dx = -1; dx <= 1; dx++) {
                        int xx = x + dx;
                        int yy = y + dy;
                        if (xx >= 0 && yy >= 0 && xx < width && yy < height) {
                            int r = yy * width + xx;
                            if (saturated[r] && !seen[r]) {
                                seen[r] = true;
                                queue.add(r);
                            }
                        }
                    }
                }
            }
            if (size >= MIN_PATCH_PX) {
                sizes.add(size);
            }
        }
        java.util.Collections.sort(sizes);
        int median = sizes.isEmpty() ? 0 : sizes.get(sizes.size() / 2);
        return new IridescenceStatistics((double) inMask / n, (double) count / n, sizes.size(), median, hueBins);
    }

    /** Saturated structural colour's share of the animal (0 when the animal is not in the frame). */
    public double saturatedShareOfShape() {
        return maskFraction > 0 ? saturatedFraction / maskFraction : 0;
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "snake %.1f %% of the frame, saturated structural colour %.2f %% of the frame "
                + "(%.1f %% of the snake) in %d patches (median %d px), %d of 12 hue bins", 100 * maskFraction,
                100 * saturatedFraction, 100 * saturatedShareOfShape(), patches, medianPatchPx, hueBins);
    }
}
