package diffract.optics.spectra;

/**
 * The precomputed Taylor-term DFTs of a height field (thesis Algorithm 1, 004 eq. {@code subdfteq}):
 * {@code DFT_n = fftshift(ifft2((i h)^n))} for n = 0..N, stored as float32 exactly as a shader receives them.
 *
 * <p>Layout of term n: row-major {@code rows x cols} texels, each an interleaved (Re, Im) pair. Texel
 * (row r, col c) holds spatial frequency index (m_x, m_y) = (c - centreCol, r - centreRow), with the zero
 * frequency at centreCol = floor(cols / 2), centreRow = floor(rows / 2) (003 eq. 1.5). Frequency index m along
 * x is m / (cols * pixelSizeXUm) cycles per micrometre. Immutable once built (the arrays are not exposed).
 */
public final class TaylorTerms {
    private final int rows;
    private final int cols;
    private final double pixelSizeXUm;
    private final double pixelSizeYUm;
    private final double maxAbsHeightUm;
    private final float[][] terms;
    /** {@link #contentSha256()}, once computed (the terms never change). */
    private volatile String contentSha256;

    /**
     * @param terms {@code terms[n]} holds term n, interleaved Re/Im, {@code 2 * rows * cols} floats; not copied:
     *              the caller hands them over
     */
    public TaylorTerms(int rows, int cols, double pixelSizeXUm, double pixelSizeYUm, double maxAbsHeightUm,
                       float[][] terms) {
        if (terms.length == 0) {
            throw new IllegalArgumentException("at least term 0 is needed");
        }
        for (float[] term : terms) {
            if (term.length != 2 * rows * cols) {
                throw new IllegalArgumentException("term of " + term.length + " floats, expected " + 2 * rows * cols);
            }
        }
        this.rows = rows;
        this.cols = cols;
        this.pixelSizeXUm = pixelSizeXUm;
        this.pixelSizeYUm = pixelSizeYUm;
        this.maxAbsHeightUm = maxAbsHeightUm;
        this.terms = terms;
    }

    public int rows() {
        return rows;
    }

    public int cols() {
        return cols;
    }

    /** Number of stored terms, N + 1. */
    public int termCount() {
        return terms.length;
    }

    /** The highest Taylor order N. */
    public int highestOrder() {
        return terms.length - 1;
    }

    public double pixelSizeXUm() {
        return pixelSizeXUm;
    }

    public double pixelSizeYUm() {
        return pixelSizeYUm;
    }

    /** max |h| of the mean-subtracted field the terms came from (for the remainder bound). */
    public double maxAbsHeightUm() {
        return maxAbsHeightUm;
    }

    /** 003 eq. 1.5: N/2 for even N, (N-1)/2 for odd N. */
    public int centreCol() {
        return cols / 2;
    }

    public int centreRow() {
        return rows / 2;
    }

    public float re(int n, int row, int col) {
        return terms[n][2 * (row * cols + col)];
    }

    public float im(int n, int row, int col) {
        return terms[n][2 * (row * cols + col) + 1];
    }

    /** A copy of term n's interleaved floats (for writers and texture upload). */
    public float[] termData(int n) {
        return terms[n].clone();
    }

    /** Direct read-only access for the hot loops of this package and writers; never modify. */
    float[] termUnsafe(int n) {
        return terms[n];
    }

    /** Per-term extremes of the real and imaginary parts: the thesis' normalisation data (003 eq. 1.1). */
    public Extrema extrema(int n) {
        float[] t = terms[n];
        double reMin = Double.POSITIVE_INFINITY;
        double reMax = Double.NEGATIVE_INFINITY;
        double imMin = Double.POSITIVE_INFINITY;
        double imMax = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < t.length; i += 2) {
            reMin = Math.min(reMin, t[i]);
            reMax = Math.max(reMax, t[i]);
            imMin = Math.min(imMin, t[i + 1]);
            imMax = Math.max(imMax, t[i + 1]);
        }
        return new Extrema(reMin, reMax, imMin, imMax);
    }

    /**
     * SHA-256 (hex) of what the terms are: sizes, pixel sizes, max |h| and every float of every term, so equal terms
     * hash equal wherever they come from (a cache keys what it makes of them by this).
     */
    public String contentSha256() {
        String known = contentSha256;
        if (known != null) {
            return known;
        }
        try {
            java.security.MessageDigest digest = java.security.MessageDigest.getInstance("SHA-256");
            java.nio.ByteBuffer header = java.nio.ByteBuffer.allocate(4 * 3 + 8 * 3).order(java.nio.ByteOrder.LITTLE_ENDIAN);
            header.putInt(rows).putInt(cols).putInt(terms.length).putDouble(pixelSizeXUm).putDouble(pixelSizeYUm)
                    .putDouble(maxAbsHeightUm);
            digest.update(header.array());
            java.nio.ByteBuffer body = java.nio.ByteBuffer.allocate(1 << 16).order(java.nio.ByteOrder.LITTLE_ENDIAN);
            for (float[] term : terms) {
                for (int i = 0; i < term.length; ) {
                    body.clear();
                    int n = Math.min(term.length - i, body.capacity() / 4);
                    body.asFloatBuffer().put(term, i, n);
                    digest.update(body.array(), 0, 4 * n);
                    i += n;
                }
            }
            known = java.util.HexFormat.of().formatHex(digest.digest());
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every Java runtime", e);
        }
        contentSha256 = known;
        return known;
    }

    /** Minimum and maximum of Re and Im of one term. */
    public record Extrema(double reMin, double reMax, double imMin, double imMax) {
    }
}
