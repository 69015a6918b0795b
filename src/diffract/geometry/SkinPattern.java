package diffract.geometry;

/**
 * A species' pigmentation painted scale by scale: each scale takes the colour of the pattern at its centre (so
 * blotch outlines follow the scales, as on the animal), darkened a little towards its rear outline and varied a
 * little from scale to scale. Colours are display sRGB (0xRRGGBB); the shaders decode them to linear light.
 */
public interface SkinPattern {
    /** The sRGB colour of the skin at a visible scale. */
    int srgb(ScaleLattice.Hit hit);

    /**
     * Pantherophis (Elaphe) guttata, the corn snake: red-orange saddles edged by a row of black scales along the
     * back, smaller edged blotches on the flanks between them, on an orange-tan ground that pales towards the
     * belly; the belly cream with black squares on alternate sides of successive ventral scales.
     */
    final class ElapheGuttata implements SkinPattern {
        /** sRGB colours picked by eye from photographs of corn snakes. */
        static final int GROUND = rgb(214, 142, 88);
        static final int GROUND_LOW = rgb(226, 182, 132);
        static final int SADDLE = rgb(190, 52, 30);
        static final int EDGE = rgb(24, 16, 12);
        static final int BELLY = rgb(236, 226, 206);
        /** Saddles along the body, head to vent (corn snakes have 30 to 50). */
        static final int SADDLES = 32;

        private final ScaleLattice lattice;
        private final ScaleLattice.Parameters p;
        private final double period;
        private final long seed;

        ElapheGuttata(ScaleLattice lattice, long seed) {
            this.lattice = lattice;
            this.p = lattice.parameters();
            this.period = (double) p.ventralScales() / SADDLES;
            this.seed = seed;
        }

        @Override
        public int srgb(ScaleLattice.Hit hit) {
            int base;
            if (hit.ventral()) {
                boolean left = hit.x() > 0;
                boolean dark = ((hit.index() & 1) == 0) == left && Math.abs(hit.x()) > 0.12 && Math.abs(hit.x()) < 0.8
                        && lattice.hash(hit.index() + seed, 77) > 0.2;
                base = dark ? EDGE : BELLY;
            } else {
                double c = hit.row() + 0.5 - p.dorsalRows() / 2.0; // rows from the back midline
                double q = hit.index() + 0.5 + 0.5 * (hit.row() & 1);
                int inside = blotch(c, q);
                if (inside != 0) {
                    // a scale of a blotch whose neighbour lies outside it is part of the black edge
                    boolean edge = blotch(c, q + 1) != inside || blotch(c, q - 1) != inside
                            || blotch(c + 1, q + 0.5) != inside || blotch(c + 1, q - 0.5) != inside
                            || blotch(c - 1, q + 0.5) != inside || blotch(c - 1, q - 0.5) != inside;
                    base = edge ? EDGE : SADDLE;
                } else {
                    double low = Math.abs(c) / (p.dorsalRows() / 2.0); // 0 on the back, 1 at the ventral edge
                    base = mix(GROUND, GROUND_LOW, smoothstep(0.55, 0.95, low));
                }
            }
            double jitter = 1 + 0.08 * (lattice.hash(hit.id() + seed, 5) - 0.5);
            return scale(base, jitter * rimShade(hit));
        }

        /** Which blotch (a number != 0) the point (c rows from the midline, q rows along) lies in, or 0. */
        private int blotch(double c, double q) {
            double halfRows = p.dorsalRows() / 2.0;
            // dorsal saddles, centred on the midline
            long n = Math.round(q / period - 0.5);
            double centre = (n + 0.5) * period + 0.6 * (lattice.hash(n + seed, 11) - 0.5);
            double size = 1 + 0.25 * (lattice.hash(n + seed, 12) - 0.5);
            if (superellipse((q - centre) / (0.4 * period * size), c / (0.4 * halfRows * size)) < 1) {
                return (int) (2 * n + 1);
            }
            // flank blotches between the saddles, on both sides
            long m = Math.round(q / period);
            double flankCentre = m * period;
            double flankSize = 1 + 0.3 * (lattice.hash(m + seed, 13 + (c > 0 ? 1 : 0)) - 0.5);
            double side = Math.abs(c) - 0.7 * halfRows;
            if (superellipse((q - flankCentre) / (0.22 * period * flankSize), side / (0.17 * halfRows * flankSize)) < 1) {
                return (int) (2 * m + 2) * (c > 0 ? 1 : -1);
            }
            return 0;
        }

        private static double superellipse(double a, double b) {
            return Math.pow(Math.pow(Math.abs(a), 4) + Math.pow(Math.abs(b), 4), 0.25);
        }
    }

    /**
     * Xenopeltis unicolor, the sunbeam snake: the back uniformly dark brown, each scale a little different, the
     * lowest dorsal rows paling towards the off-white belly.
     */
    final class XenopeltisUnicolor implements SkinPattern {
        static final int BACK = rgb(58, 42, 34);
        static final int BELLY = rgb(214, 208, 196);

        private final ScaleLattice lattice;
        private final ScaleLattice.Parameters p;
        private final long seed;

        XenopeltisUnicolor(ScaleLattice lattice, long seed) {
            this.lattice = lattice;
            this.p = lattice.parameters();
            this.seed = seed;
        }

        @Override
        public int srgb(ScaleLattice.Hit hit) {
            int base;
            if (hit.ventral()) {
                base = BELLY;
            } else {
                int fromVentral = Math.min(hit.row(), p.dorsalRows() - 1 - hit.row());
                double pale = fromVentral == 0 ? 0.55 : fromVentral == 1 ? 0.2 : 0;
                base = mix(BACK, BELLY, pale);
            }
            double jitter = 1 + 0.16 * (lattice.hash(hit.id() + seed, 5) - 0.5);
            return scale(base, jitter * rimShade(hit));
        }
    }

    /** Darker towards the scale's outline: the rear edge casts a little shadow, the front lies under a neighbour. */
    private static double rimShade(ScaleLattice.Hit hit) {
        return 1 - 0.25 * smoothstep(0.75, 1.0, hit.rim());
    }

    static int rgb(int r, int g, int b) {
        return (r << 16) | (g << 8) | b;
    }

    /** a + (b - a) t per channel, in display sRGB (colours picked by eye are blended as they were picked). */
    static int mix(int a, int b, double t) {
        int out = 0;
        for (int shift = 16; shift >= 0; shift -= 8) {
            double ca = (a >> shift) & 0xFF;
            double cb = (b >> shift) & 0xFF;
            out |= ((int) Math.round(ca + (cb - ca) * t)) << shift;
        }
        return out;
    }

    static int scale(int rgb, double factor) {
        int out = 0;
        for (int shift = 16; shift >= 0; shift -= 8) {
            out |= ((int) Math.round(Math.max(0, Math.min(255, ((rgb >> shift) & 0xFF) * factor)))) << shift;
        }
        return out;
    }

    static double smoothstep(double edge0, double edge1, double x) {
        double f = Math.min(1, Math.max(0, (x - edge0) / (edge1 - edge0)));
        return f * f * (3 - 2 * f);
    }
}
