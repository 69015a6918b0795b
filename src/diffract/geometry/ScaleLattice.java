package diffract.geometry;

import diffract.util.UserInputException;

/**
 * The scales of a snake in the skin's own coordinates: u around the body (0 and 1 on the belly midline, 0.5 on
 * the back, as {@link SnakeMesh}'s texture coordinate) and q along it, counted in scale rows from the snout.
 *
 * <p>Layout, as snakes have it: a band of wide ventral scales along the belly ({@code ventralFraction} of the
 * circumference), one per unit of q; on the rest, {@code dorsalRows} longitudinal rows of dorsal scales, each row
 * shifted by half a scale against its neighbours, so the scale centres form a diamond (rhombic) lattice with
 * centres at (row k, q = j + 1/2 + (k mod 2) / 2). The lattice's cell around a centre is the diamond with
 * half-diagonals of one row width around the body and half a row along it.
 *
 * <p>Overlap (imbrication): each scale's footprint is an ellipse through the corners of its diamond, enlarged by
 * {@code overlap}; where footprints overlap, the scale whose own footprint the point lies furthest back in wins,
 * i.e. a scale's free rear edge lies on top of the front of the scales behind it, as on a snake. The visible
 * outline of each scale is therefore the rounded rear arc of its footprint.
 *
 * <p>Shape: each scale is a tilted dome, h = tan(tilt) x' + tan(roll) y' + H (1 - (x/a)^2 - (y/c)^2), where x', y'
 * are the scale's own axes (x' along its long axis, towards the tail), x, y the body's (along, around) offsets from
 * the scale's centre and a, c its footprint's semi-axes (metres), with H = tan(domeSlope) min(a, c) / 2 so the
 * dome's slope within the footprint never exceeds {@code domeSlopeDeg}.
 * Tilt (the rear edge lifted), roll and the long axis's yaw vary from scale to scale by seeded jitter.
 * {@link #frame} gives the visible surface's unit normal and the scale's long axis in the body's frame
 * (along the body towards the tail, around it in the direction of increasing u, out of the skin).
 */
public final class ScaleLattice {
    /**
     * @param dorsalRows       dorsal scale rows around the body at mid-body (a taxonomic count, 13..41)
     * @param ventralScales    ventral scales from the head to the vent (a taxonomic count, 100..400)
     * @param ventralFraction  fraction of the circumference the ventral scales cover (0.1..0.45)
     * @param domeSlopeDeg     slope of each scale's dome at the end of its shorter axis, degrees (0..40)
     * @param tiltDeg          mean tilt of each scale along its long axis, rear edge up, degrees (0..30)
     * @param tiltJitterDeg    standard deviation of tilt and roll from scale to scale, degrees (0..20)
     * @param yawJitterDeg     standard deviation of the long axis's direction from scale to scale, degrees (0..30)
     * @param overlap          footprint size relative to the ellipse through the diamond's corners (1.15..1.6)
     * @param seed             seed of the jitter
     */
    public record Parameters(int dorsalRows, int ventralScales, double ventralFraction, double domeSlopeDeg,
                             double tiltDeg, double tiltJitterDeg, double yawJitterDeg, double overlap, long seed) {
        public Parameters {
            check("dorsalRows", dorsalRows, 5, 61);
            check("ventralScales", ventralScales, 20, 600);
            check("ventralFraction", ventralFraction, 0.05, 0.45);
            check("domeSlopeDeg", domeSlopeDeg, 0, 40);
            check("tiltDeg", tiltDeg, 0, 30);
            check("tiltJitterDeg", tiltJitterDeg, 0, 20);
            check("yawJitterDeg", yawJitterDeg, 0, 30);
            check("overlap", overlap, 1.15, 1.6);
        }

        private static void check(String name, double value, double min, double max) {
            if (!(value >= min && value <= max)) {
                throw new UserInputException("scales " + name + " must be in [" + SnakeSpecies.format(min) + ", "
                        + SnakeSpecies.format(max) + "], got " + SnakeSpecies.format(value));
            }
        }

        public Parameters withSeed(long newSeed) {
            return new Parameters(dorsalRows, ventralScales, ventralFraction, domeSlopeDeg, tiltDeg, tiltJitterDeg,
                    yawJitterDeg, overlap, newSeed);
        }
    }

    /**
     * The scale seen at a point.
     *
     * @param ventral  a ventral scale (else dorsal)
     * @param row      dorsal row, 0 next to the ventral scales on the side of increasing u; -1 for ventral scales
     * @param index    the scale's number along its row (q of its centre, rounded down)
     * @param x        around the body from the scale's centre, in row widths (ventral: in half-widths of the band)
     * @param y        along the body from the scale's centre, in row lengths (towards the tail positive)
     * @param rim      how far out in its footprint the point lies: 0 at the centre, 1 on the outline
     * @param covered  true when no footprint holds the point and the nearest scale stands in (never, for a
     *                 lattice whose footprints cover its cells; tests check that)
     */
    public record Hit(boolean ventral, int row, long index, double x, double y, double rim, boolean covered) {
        /** A number that names the scale (for seeded per-scale choices). */
        public long id() {
            return ventral ? index * 131 + 7 : index * 131 + 11 + row;
        }
    }

    private final Parameters p;

    public ScaleLattice(Parameters parameters) {
        this.p = parameters;
    }

    public Parameters parameters() {
        return p;
    }

    /** Dorsal coordinate: 0 at the ventral band's edge near u = ventralFraction / 2, dorsalRows at the other edge. */
    double dorsalRowCoordinate(double u) {
        double half = p.ventralFraction() / 2;
        return (wrap(u) - half) / (1 - p.ventralFraction()) * p.dorsalRows();
    }

    /** Whether u lies on the ventral band. */
    public boolean onVentralBand(double u) {
        double w = wrap(u);
        return Math.min(w, 1 - w) < p.ventralFraction() / 2;
    }

    /** The visible scale at (u, q). */
    public Hit visible(double u, double q) {
        double fp = p.overlap();
        if (onVentralBand(u)) {
            double w = wrap(u);
            double x = (w < 0.5 ? w : w - 1) / (p.ventralFraction() / 2); // -1..1 across the band
            long j0 = (long) Math.floor(q);
            Hit best = null;
            double bestStack = Double.NEGATIVE_INFINITY;
            for (long j = j0 - 1; j <= j0 + 1; j++) {
                double y = q - (j + 0.5);
                // the rear edge is a shallow arc: the plate is a little longer on the midline than at its sides
                double halfLength = 0.5 * fp * (1 - 0.12 * x * x);
                double rim = Math.abs(y) / halfLength;
                if (rim <= 1 && y / halfLength > bestStack) {
                    bestStack = y / halfLength;
                    best = new Hit(true, -1, j, x, y, Math.max(rim, Math.abs(x)), false);
                }
            }
            return best != null ? best : new Hit(true, -1, j0, x, q - (j0 + 0.5), 1, true);
        }
        double r = dorsalRowCoordinate(u);
        int k0 = (int) Math.floor(r);
        Hit best = null;
        double bestStack = Double.NEGATIVE_INFINITY;
        Hit nearest = null;
        double nearestRim = Double.POSITIVE_INFINITY;
        double semiAround = fp; // the ellipse through the corners (+-1, 0), (0, +-1/2) has semi-axes 1 and 1/2
        double semiAlong = 0.5 * fp;
        for (int k = k0 - 1; k <= k0 + 1; k++) {
            if (k < 0 || k >= p.dorsalRows()) {
                continue;
            }
            double offset = 0.5 * (k & 1);
            double x = r - (k + 0.5);
            long j0 = (long) Math.floor(q - offset);
            for (long j = j0 - 1; j <= j0 + 1; j++) {
                double y = q - (j + 0.5 + offset);
                double rim = Math.sqrt(sq(x / semiAround) + sq(y / semiAlong));
                if (rim <= 1) {
                    double stack = y / semiAlong;
                    if (stack > bestStack) {
                        bestStack = stack;
                        best = new Hit(false, k, j, x, y, rim, false);
                    }
                } else if (rim < nearestRim) {
                    nearestRim = rim;
                    nearest = new Hit(false, k, j, x, y, rim, true);
                }
            }
        }
        return best != null ? best : nearest;
    }

    /**
     * The visible surface at a hit: {nAlong, nAround, nOut, axisAlong, axisAround}, a unit normal and the scale's
     * unit long axis in the tangent plane, both in the body's frame (along towards the tail, around towards
     * increasing u, out of the skin).
     *
     * @param rowWidthM  one dorsal row's width around the body here, metres (ventral: the band's half-width)
     * @param rowLengthM one row's length along the body here, metres
     */
    public double[] frame(Hit hit, double rowWidthM, double rowLengthM) {
        double fp = p.overlap();
        double yaw = Math.toRadians(p.yawJitterDeg()) * gaussian(hit.id(), 1);
        double tilt = Math.toRadians(p.tiltDeg() + p.tiltJitterDeg() * gaussian(hit.id(), 2));
        double roll = Math.toRadians(p.tiltJitterDeg() * gaussian(hit.id(), 3));
        // physical offsets from the centre (metres) and semi-axes of the footprint
        double along = hit.y() * rowLengthM;
        double around = hit.x() * rowWidthM;
        double semiAlong = 0.5 * fp * rowLengthM;
        double semiAround = (hit.ventral() ? 1.0 : fp) * rowWidthM;
        if (hit.ventral()) {
            yaw *= 0.25; // a ventral plate spans the belly: it cannot turn much
            roll *= 0.25;
        }
        double cos = Math.cos(yaw);
        double sin = Math.sin(yaw);
        // the dome lies in the footprint's own axes (so its slope never exceeds domeSlopeDeg inside it); tilt and
        // roll turn with the scale's long axis
        double dome = Math.tan(Math.toRadians(p.domeSlopeDeg())) * Math.min(semiAlong, semiAround) / 2;
        double gAlong = -2 * dome * along / (semiAlong * semiAlong) + cos * Math.tan(tilt) - sin * Math.tan(roll);
        double gAround = -2 * dome * around / (semiAround * semiAround) + sin * Math.tan(tilt) + cos * Math.tan(roll);
        double norm = Math.sqrt(gAlong * gAlong + gAround * gAround + 1);
        return new double[] {-gAlong / norm, -gAround / norm, 1 / norm, cos, sin};
    }

    /** A standard normal number per (scale, channel), seeded: the same scale always gets the same jitter. */
    double gaussian(long id, int channel) {
        double u1 = Math.max(1e-12, hash(id, channel));
        double u2 = hash(id, channel + 100);
        return Math.sqrt(-2 * Math.log(u1)) * Math.cos(2 * Math.PI * u2);
    }

    /** A uniform number in [0, 1) per (scale, channel), seeded (SplitMix64's finaliser). */
    public double hash(long id, long channel) {
        long z = p.seed() * 0x9E3779B97F4A7C15L + id * 0xBF58476D1CE4E5B9L + channel * 0x94D049BB133111EBL;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        z ^= z >>> 31;
        return (z >>> 11) * 0x1.0p-53;
    }

    static double wrap(double u) {
        return u - Math.floor(u);
    }

    private static double sq(double x) {
        return x * x;
    }
}
