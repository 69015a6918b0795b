package diffract.render;

/** IEEE 754 binary16 rounding of a float (round to nearest even, subnormals kept), as an RG16F texture stores it. */
final class HalfFloat {
    /** The largest finite half, 65504; from 65520 on a float rounds to infinity. */
    static final float MAX = 65504f;

    private HalfFloat() {
    }

    static float rounded(float f) {
        if (f == 0 || !Float.isFinite(f)) {
            return f;
        }
        float a = Math.abs(f);
        if (a >= 65520f) {
            return Math.copySign(Float.POSITIVE_INFINITY, f);
        }
        // 11 significant bits for normal halves (exponent >= -14); a fixed quantum of 2^-24 for subnormal ones
        int quantumExponent = Math.max(Math.getExponent(a), -14) - 10;
        double quantum = Math.scalb(1.0, quantumExponent);
        return (float) Math.copySign(Math.rint(a / quantum) * quantum, f);
    }
}
