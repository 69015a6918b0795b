package diffract.geometry;

/** A 3-vector in double precision, for building meshes; package-private because the public API uses float arrays. */
record Vec3(double x, double y, double z) {
    static final Vec3 ZERO = new Vec3(0, 0, 0);

    static Vec3 at(float[] xyz, int vertex) {
        return new Vec3(xyz[3 * vertex], xyz[3 * vertex + 1], xyz[3 * vertex + 2]);
    }

    Vec3 plus(Vec3 o) {
        return new Vec3(x + o.x, y + o.y, z + o.z);
    }

    Vec3 minus(Vec3 o) {
        return new Vec3(x - o.x, y - o.y, z - o.z);
    }

    Vec3 times(double s) {
        return new Vec3(x * s, y * s, z * s);
    }

    double dot(Vec3 o) {
        return x * o.x + y * o.y + z * o.z;
    }

    Vec3 cross(Vec3 o) {
        return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }

    double length() {
        return Math.sqrt(dot(this));
    }

    /** This vector scaled to length 1; the zero vector stays zero (callers test {@link #length()} first). */
    Vec3 normalized() {
        double length = length();
        return length == 0 ? this : times(1.0 / length);
    }

    /** The part of this vector orthogonal to the unit vector {@code n}: its projection onto the tangent plane. */
    Vec3 projectedOff(Vec3 n) {
        return minus(n.times(dot(n)));
    }

    /** Some unit vector orthogonal to the unit vector {@code n} (for where a tangent field is undefined). */
    static Vec3 anyPerpendicular(Vec3 n) {
        Vec3 axis = Math.abs(n.x) < 0.9 ? new Vec3(1, 0, 0) : new Vec3(0, 1, 0);
        return axis.projectedOff(n).normalized();
    }

    void store(float[] xyz, int vertex) {
        xyz[3 * vertex] = (float) x;
        xyz[3 * vertex + 1] = (float) y;
        xyz[3 * vertex + 2] = (float) z;
    }
}
