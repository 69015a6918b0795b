package diffract.geometry;

import diffract.util.UserInputException;

/**
 * A procedural snake: a tapered tube of elliptic cross-section swept along a smooth 3-D centre curve, closed by a
 * rounded snout and a pointed tail tip. It stands in for the 3-D scan of an Elaphe the thesis rendered, which is
 * not public.
 *
 * <p>Coordinates: y is up, the snake lies on the ground plane y = 0 with its belly touching it, the head at
 * +x (x = +length/2), the body bending left and right in z, the head lifted a little. Units: metres.
 *
 * <p>Topology: {@code rings} rings of {@code segments + 1} vertices (the first and last of each ring share a
 * position: the texture seam runs along the belly) plus one pole vertex per segment at each end (all at the
 * same position, each with its own u). {@code 2 * rings * segments} triangles; the surface is closed once equal
 * positions are welded ({@link Mesh#isClosed()}).
 *
 * <p>Texture coordinates: u runs around the body, 0 (and 1) on the belly midline, 0.5 on the back midline;
 * v runs along it, 0 at the snout tip and 1 at the tail tip, proportional to the distance along the surface.
 *
 * <p>Tangents are the nanostructure patch's orientation (its x axis, along which the ridges of the measured
 * Elaphe patch run): by default the centre curve's tangent projected onto the surface, so the ridges run along
 * the body as on real snakes; {@link RidgeDirection#AROUND_BODY} turns them by 90 degrees. A tangent field on a
 * closed surface must vanish somewhere (hairy-ball theorem): at the two poles the along-body field is
 * undefined and they use the up direction of the centre curve's frame instead.
 */
public final class SnakeMesh {
    /** How the patch's x axis (its ridges, for the Elaphe-like patches) lies on the skin. */
    public enum RidgeDirection {
        /** Along the body, head to tail: as on real snakes. */
        ALONG_BODY,
        /** Around the body, in the direction of increasing u. */
        AROUND_BODY
    }

    /** How the body lies on the ground. */
    public enum Pose {
        /** Stretched out along x in lateral S-bends (the default). */
        S_CURVE,
        /**
         * Resting in a flat coil: the centre curve is an Archimedean spiral on the ground, tail in the middle, head
         * at the outer end, coils one body width plus a tenth apart, so neighbouring coils never touch.
         */
        COILED
    }

    /**
     * The body along its length, at each ring: what a scale lattice needs to size its scales.
     *
     * @param v             texture coordinate v of each ring (0 at the snout tip, 1 at the tail tip)
     * @param halfWidthM    half-width of the cross-section at each ring, metres
     * @param heightToWidth cross-section height over width
     * @param lengthAlongM  distance along the body's side from snout tip to tail tip, metres (v is proportional to it)
     * @param ventV         v at which the tail begins (the vent)
     */
    public record Profile(double[] v, double[] halfWidthM, double heightToWidth, double lengthAlongM, double ventV) {
        /** Perimeter of the elliptic cross-section at ring i (Ramanujan's approximation), metres. */
        public double circumferenceM(int i) {
            double a = halfWidthM[i];
            double b = a * heightToWidth;
            double h = (a - b) * (a - b) / ((a + b) * (a + b));
            return Math.PI * (a + b) * (1 + 3 * h / (10 + Math.sqrt(4 - 3 * h)));
        }
    }

    /** Fine samples of the centre curve used to place rings evenly along the surface. */
    private static final int PROFILE_SAMPLES = 8192;

    /**
     * The snake's shape and resolution.
     *
     * @param lengthM            extent of the centre curve along x, metres (the curve itself is longer by its bends)
     * @param radiusM            largest half-width of the body, metres (mid-body)
     * @param heightToWidth      cross-section height over width (&lt; 1: the body is a little flattened)
     * @param tailFraction       fraction of the length over which the tail tapers to its tip
     * @param bends              number of whole sine waves of the lateral (z) bends
     * @param bendAmplitudeM     amplitude of the lateral bends, metres
     * @param headLiftM          how far the snout is raised above the body line, metres
     * @param rings              rings of vertices between the two poles
     * @param segments           vertices around each ring (+1 for the seam)
     * @param ridges             patch orientation on the skin
     * @param pose               stretched out in S-bends, or coiled (the centre curve; the cross-section is the same)
     */
    public record Parameters(double lengthM, double radiusM, double heightToWidth, double tailFraction,
                             double bends, double bendAmplitudeM, double headLiftM, int rings, int segments,
                             RidgeDirection ridges, Pose pose) {
        public Parameters {
            if (pose == null) {
                throw new UserInputException("snake pose missing");
            }
            requirePositive("lengthM", lengthM);
            requirePositive("radiusM", radiusM);
            if (!(radiusM < lengthM / 8)) {
                throw new UserInputException("snake radiusM " + radiusM + " must be less than lengthM / 8 ("
                        + lengthM / 8 + "): a snake is long and thin");
            }
            if (!(heightToWidth > 0.2 && heightToWidth <= 2)) {
                throw new UserInputException("snake heightToWidth must be in (0.2, 2], got " + heightToWidth);
            }
            if (!(tailFraction > 0.02 && tailFraction < 0.8)) {
                throw new UserInputException("snake tailFraction must be in (0.02, 0.8), got " + tailFraction);
            }
            if (!(bends >= 0 && bends <= 10)) {
                throw new UserInputException("snake bends must be in [0, 10], got " + bends);
            }
            if (!(bendAmplitudeM >= 0 && bendAmplitudeM <= lengthM)) {
                throw new UserInputException("snake bendAmplitudeM must be in [0, lengthM], got " + bendAmplitudeM);
            }
            if (!(headLiftM >= 0 && headLiftM <= lengthM / 4)) {
                throw new UserInputException("snake headLiftM must be in [0, lengthM / 4], got " + headLiftM);
            }
            if (rings < 8 || rings > 4096 || segments < 8 || segments > 1024) {
                throw new UserInputException("snake rings must be in [8, 4096] and segments in [8, 1024], got "
                        + rings + " and " + segments);
            }
            if (ridges == null) {
                throw new UserInputException("snake ridge direction missing");
            }
        }

        /**
         * A corn-snake-sized animal: 1.2 m, 2 cm half-width, two and a half bends of 12 cm, 320 rings x 64
         * segments = 40,960 triangles, ridges along the body, stretched out in S-bends.
         */
        public static Parameters defaults() {
            return new Parameters(1.2, 0.02, 0.85, 0.25, 2.5, 0.12, 0.03, 320, 64, RidgeDirection.ALONG_BODY,
                    Pose.S_CURVE);
        }

        public Parameters withRidges(RidgeDirection direction) {
            return new Parameters(lengthM, radiusM, heightToWidth, tailFraction, bends, bendAmplitudeM, headLiftM,
                    rings, segments, direction, pose);
        }

        public Parameters withResolution(int newRings, int newSegments) {
            return new Parameters(lengthM, radiusM, heightToWidth, tailFraction, bends, bendAmplitudeM, headLiftM,
                    newRings, newSegments, ridges, pose);
        }

        public Parameters withPose(Pose newPose) {
            return new Parameters(lengthM, radiusM, heightToWidth, tailFraction, bends, bendAmplitudeM, headLiftM,
                    rings, segments, ridges, newPose);
        }

        /** Triangles the mesh will have: 2 per quad of the tube, and one fan per cap. */
        public int triangleCount() {
            return 2 * rings * segments;
        }

        private static void requirePositive(String name, double value) {
            if (!(value > 0) || !Double.isFinite(value)) {
                throw new UserInputException("snake " + name + " must be a positive number of metres, got " + value);
            }
        }
    }

    private final Parameters parameters;
    private final Mesh mesh;
    private final float[] centreCurvePoints;
    private final Profile profile;

    private SnakeMesh(Parameters parameters, Mesh mesh, float[] centreCurvePoints, Profile profile) {
        this.parameters = parameters;
        this.mesh = mesh;
        this.centreCurvePoints = centreCurvePoints;
        this.profile = profile;
    }

    /** The body's width along its length, ring by ring. */
    public Profile profile() {
        return new Profile(profile.v().clone(), profile.halfWidthM().clone(), profile.heightToWidth(),
                profile.lengthAlongM(), profile.ventV());
    }

    public Parameters parameters() {
        return parameters;
    }

    public Mesh mesh() {
        return mesh;
    }

    /**
     * For each vertex, the centre-curve point its ring was built around (for the poles, that of the nearest ring):
     * the vector from it to the vertex points out of the body.
     */
    public float[] centreCurvePoints() {
        return centreCurvePoints.clone();
    }

    /** Builds the snake. Deterministic: the same parameters give the same mesh. */
    public static SnakeMesh generate(Parameters p) {
        Body body = new Body(p);
        double[] ringT = body.ringParameters();
        int rings = p.rings();
        int segments = p.segments();
        int ringStride = segments + 1;
        int headPoles = rings * ringStride;
        int tailPoles = headPoles + segments;
        int vertexCount = tailPoles + segments;

        float[] positions = new float[3 * vertexCount];
        float[] uvs = new float[2 * vertexCount];
        float[] centres = new float[3 * vertexCount];
        Vec3[] alongBody = new Vec3[vertexCount];
        Vec3[] up = new Vec3[vertexCount];

        for (int i = 0; i < rings; i++) {
            double t = ringT[i];
            Vec3 centre = body.centre(t);
            Frame frame = body.frame(t);
            double halfWidth = body.radius(t);
            double halfHeight = halfWidth * p.heightToWidth();
            for (int j = 0; j <= segments; j++) {
                // j == segments repeats j == 0 exactly, so seam positions are bit-identical and weld
                double theta = 2 * Math.PI * (j % segments) / segments;
                Vec3 offset = frame.side.times(Math.sin(theta) * halfWidth)
                        .plus(frame.up.times(-Math.cos(theta) * halfHeight));
                int v = i * ringStride + j;
                centre.plus(offset).store(positions, v);
                centre.store(centres, v);
                uvs[2 * v] = (float) j / segments;
                uvs[2 * v + 1] = (float) ((i + 1.0) / (rings + 1)); // rings are evenly spaced along the surface
                alongBody[v] = frame.along;
                up[v] = frame.up;
            }
        }
        Vec3 snout = body.centre(0);
        Vec3 tailTip = body.centre(1);
        Frame headFrame = body.frame(0);
        Frame tailFrame = body.frame(1);
        for (int j = 0; j < segments; j++) {
            placePole(headPoles + j, snout, body.centre(ringT[0]), (j + 0.5) / segments, 0, headFrame,
                    positions, centres, uvs, alongBody, up);
            placePole(tailPoles + j, tailTip, body.centre(ringT[rings - 1]), (j + 0.5) / segments, 1, tailFrame,
                    positions, centres, uvs, alongBody, up);
        }

        int[] triangles = new int[3 * p.triangleCount()];
        int k = 0;
        for (int i = 0; i + 1 < rings; i++) {
            for (int j = 0; j < segments; j++) {
                int a = i * ringStride + j;
                int b = a + 1;
                int c = a + ringStride;
                int d = c + 1;
                // counter-clockwise seen from outside: (a, c, b) turns from the along-body edge to the around edge
                k = put(triangles, k, a, c, b);
                k = put(triangles, k, b, c, d);
            }
        }
        int lastRing = (rings - 1) * ringStride;
        for (int j = 0; j < segments; j++) {
            k = put(triangles, k, headPoles + j, j, j + 1);
            k = put(triangles, k, lastRing + j, tailPoles + j, lastRing + j + 1);
        }

        float[] normals = SurfaceFrames.toFloats(SurfaceFrames.smoothNormals(positions, triangles));
        Vec3[] directions = new Vec3[vertexCount];
        for (int v = 0; v < vertexCount; v++) {
            Vec3 n = Vec3.at(normals, v);
            Vec3 along = alongBody[v].projectedOff(n);
            if (along.length() < 1e-3) {
                along = up[v].projectedOff(n); // a pole: the along-body field is undefined here
            }
            along = along.normalized();
            directions[v] = p.ridges() == RidgeDirection.ALONG_BODY ? along : n.cross(along);
        }
        float[] tangents = SurfaceFrames.tangentsFrom(normals, directions);
        double[] ringV = new double[rings];
        double[] ringHalfWidth = new double[rings];
        double ventV = 1;
        for (int i = rings - 1; i >= 0; i--) {
            ringV[i] = (i + 1.0) / (rings + 1);
            ringHalfWidth[i] = body.radius(ringT[i]);
            if (ringT[i] >= 1 - p.tailFraction()) {
                ventV = ringV[i];
            }
        }
        Profile profile = new Profile(ringV, ringHalfWidth, p.heightToWidth(), body.surfaceLengthM(), ventV);
        return new SnakeMesh(p, Mesh.of(positions, normals, tangents, uvs, triangles), centres, profile);
    }

    private static void placePole(int v, Vec3 pole, Vec3 nearestRingCentre, double u, double vCoordinate,
                                  Frame frame, float[] positions, float[] centres, float[] uvs, Vec3[] along,
                                  Vec3[] up) {
        pole.store(positions, v);
        nearestRingCentre.store(centres, v);
        uvs[2 * v] = (float) u;
        uvs[2 * v + 1] = (float) vCoordinate;
        along[v] = frame.along;
        up[v] = frame.up;
    }

    private static int put(int[] triangles, int k, int a, int b, int c) {
        triangles[k] = a;
        triangles[k + 1] = b;
        triangles[k + 2] = c;
        return k + 3;
    }

    /** Orthonormal frame of the centre curve: along (head to tail), up (towards +y), side = along x up. */
    private record Frame(Vec3 along, Vec3 up, Vec3 side) {
    }

    /** The centre curve and radius profile as functions of t in [0, 1], 0 at the snout tip, 1 at the tail tip. */
    private static final class Body {
        private static final Vec3 WORLD_UP = new Vec3(0, 1, 0);
        private final Parameters p;
        /** t at which the snout's rounding ends: about one head radius behind the tip. */
        private final double snoutT;
        /** COILED: spiral angle (radians, 0 at the inner end) at fine samples of t, so t follows arc length. */
        private final double[] coilAngle;
        private final double coilInnerRadiusM;
        private final double coilSpacingM;

        Body(Parameters p) {
            this.p = p;
            this.snoutT = 0.8 * p.radiusM() / p.lengthM();
            this.coilSpacingM = 2.2 * p.radiusM() * 1.3; // the head bulge is 1.3 radii wide, plus a gap
            this.coilInnerRadiusM = 2.0 * p.radiusM();
            this.coilAngle = p.pose() == Pose.COILED ? coilAngles() : null;
        }

        /**
         * The spiral r(phi) = r0 + b phi / (2 pi) sampled so that equal steps of t are equal steps of arc length
         * (ds = sqrt(r^2 + (b / 2 pi)^2) dphi), t = 1 (the tail tip) at phi = 0.
         */
        private double[] coilAngles() {
            int n = PROFILE_SAMPLES;
            double dPhi = 1e-3;
            double[] angleAt = new double[n + 1];
            double phi = 0;
            double s = 0;
            double bOver2Pi = coilSpacingM / (2 * Math.PI);
            for (int k = 0; k <= n; k++) {
                double target = p.lengthM() * k / n;
                while (s < target) {
                    double r = coilInnerRadiusM + bOver2Pi * phi;
                    s += Math.sqrt(r * r + bOver2Pi * bOver2Pi) * dPhi;
                    phi += dPhi;
                }
                angleAt[k] = phi;
            }
            return angleAt;
        }

        /** The distance along the side from snout tip to tail tip, metres. */
        double surfaceLengthM() {
            return cumulativeSurfaceDistance()[PROFILE_SAMPLES];
        }

        /** Half-width along the body before the two tips are rounded: neck, head bulge, body, tail taper. */
        private double girth(double t) {
            double neckToBody = 0.6 + 0.4 * smoothstep(0.03, 0.3, t);
            double head = 0.3 * Math.exp(-sq((t - 2.2 * snoutT) / (1.6 * snoutT)));
            return p.radiusM() * (neckToBody + head);
        }

        double radius(double t) {
            double snout = Math.sqrt(Math.max(0, 1 - sq(1 - Math.min(t / snoutT, 1))));
            double tailStart = 1 - p.tailFraction();
            // exponent < 1: the radius reaches 0 at the tip with an infinite slope, i.e. a rounded point
            double tail = t <= tailStart ? 1 : Math.pow(Math.max(0, (1 - t) / p.tailFraction()), 0.7);
            return girth(t) * snout * tail;
        }

        Vec3 centre(double t) {
            double x = p.lengthM() * (0.5 - t);
            // the belly rests on y = 0; the tail's centre sinks less than its radius so the tip stays above ground
            double bodyHeight = p.heightToWidth() * girth(t) * (1 - 0.6 * smoothstep(1 - p.tailFraction(), 1, t));
            double lift = p.headLiftM() * sq(1 - smoothstep(0, 0.12, t));
            if (p.pose() == Pose.COILED) {
                double f = (1 - t) * PROFILE_SAMPLES;
                int k = Math.min(PROFILE_SAMPLES - 1, (int) Math.floor(f));
                double phi = coilAngle[k] + (f - k) * (coilAngle[k + 1] - coilAngle[k]);
                double r = coilInnerRadiusM + coilSpacingM * phi / (2 * Math.PI);
                return new Vec3(r * Math.cos(phi), bodyHeight + lift, r * Math.sin(phi));
            }
            double calmHead = 0.3 + 0.7 * smoothstep(0, 0.15, t);
            double z = p.bendAmplitudeM() * Math.sin(2 * Math.PI * p.bends() * t) * calmHead;
            return new Vec3(x, bodyHeight + lift, z);
        }

        Frame frame(double t) {
            double h = 1e-5;
            double t0 = Math.max(0, t - h);
            double t1 = Math.min(1, t + h);
            Vec3 along = centre(t1).minus(centre(t0)).normalized();
            Vec3 up = WORLD_UP.projectedOff(along).normalized();
            return new Frame(along, up, along.cross(up));
        }

        /**
         * t of each ring, spaced evenly in distance along the surface's side (the curve traced by centre and
         * radius together), so rings crowd where the radius changes fast, at the snout and the tail tip, and
         * the caps come out round.
         */
        double[] ringParameters() {
            double[] cumulative = cumulativeSurfaceDistance();
            double total = cumulative[PROFILE_SAMPLES];
            double[] ts = new double[p.rings()];
            int sample = 0;
            for (int i = 0; i < ts.length; i++) {
                double target = total * (i + 1) / (ts.length + 1);
                while (cumulative[sample + 1] < target) {
                    sample++;
                }
                double f = (target - cumulative[sample]) / (cumulative[sample + 1] - cumulative[sample]);
                ts[i] = (sample + f) / PROFILE_SAMPLES;
            }
            return ts;
        }

        private double[] cumulativeSurfaceDistance() {
            double[] cumulative = new double[PROFILE_SAMPLES + 1];
            Vec3 previous = centre(0);
            double previousRadius = radius(0);
            for (int s = 1; s <= PROFILE_SAMPLES; s++) {
                double t = (double) s / PROFILE_SAMPLES;
                Vec3 c = centre(t);
                double r = radius(t);
                double step = Math.sqrt(c.minus(previous).dot(c.minus(previous)) + sq(r - previousRadius));
                cumulative[s] = cumulative[s - 1] + step;
                previous = c;
                previousRadius = r;
            }
            return cumulative;
        }

        private static double smoothstep(double edge0, double edge1, double x) {
            double f = Math.min(1, Math.max(0, (x - edge0) / (edge1 - edge0)));
            return f * f * (3 - 2 * f);
        }

        private static double sq(double x) {
            return x * x;
        }
    }
}
