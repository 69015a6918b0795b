package diffract.optics.patches;

import diffract.util.UserInputException;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/**
 * A measured or synthetic nanostructure: heights in micrometres on a regular grid.
 *
 * <p>Layout: {@code rows x cols} samples, row-major. Column index grows along the tangent frame's x axis,
 * row index along its y axis (the BRDF-map convention), so sample (row r, col c) sits at
 * (x, y) = (c * pixelSizeXUm, r * pixelSizeYUm). Immutable.
 */
public final class HeightField {
    private final int rows;
    private final int cols;
    private final double[] heightsUm;
    private final double pixelSizeXUm;
    private final double pixelSizeYUm;

    private HeightField(int rows, int cols, double[] heightsUm, double pixelSizeXUm, double pixelSizeYUm) {
        this.rows = rows;
        this.cols = cols;
        this.heightsUm = heightsUm;
        this.pixelSizeXUm = pixelSizeXUm;
        this.pixelSizeYUm = pixelSizeYUm;
    }

    /**
     * @param heightsUm row-major heights, copied
     * @throws UserInputException for an empty grid, a size mismatch, a non-finite height or pixel size
     */
    public static HeightField of(int rows, int cols, double[] heightsUm, double pixelSizeXUm, double pixelSizeYUm) {
        if (rows <= 0 || cols <= 0) {
            throw new UserInputException("the height field is empty (" + rows + " x " + cols + " samples)");
        }
        if (heightsUm.length != (long) rows * cols) {
            throw new UserInputException("the height field has " + heightsUm.length + " values, expected "
                    + rows + " x " + cols);
        }
        requirePixelSize(pixelSizeXUm);
        requirePixelSize(pixelSizeYUm);
        for (int i = 0; i < heightsUm.length; i++) {
            if (!Double.isFinite(heightsUm[i])) {
                throw new UserInputException("the height field has a non-finite value (" + heightsUm[i]
                        + ") at row " + (i / cols) + ", column " + (i % cols) + "; fill or crop missing data first");
            }
        }
        return new HeightField(rows, cols, heightsUm.clone(), pixelSizeXUm, pixelSizeYUm);
    }

    public static HeightField of(int rows, int cols, double[] heightsUm, double pixelSizeUm) {
        return of(rows, cols, heightsUm, pixelSizeUm, pixelSizeUm);
    }

    private static void requirePixelSize(double pixelSizeUm) {
        if (!(pixelSizeUm > 0) || !Double.isFinite(pixelSizeUm)) {
            throw new UserInputException("the pixel size must be a positive number of micrometres, got " + pixelSizeUm);
        }
    }

    public int rows() {
        return rows;
    }

    public int cols() {
        return cols;
    }

    public int sampleCount() {
        return rows * cols;
    }

    public double pixelSizeXUm() {
        return pixelSizeXUm;
    }

    public double pixelSizeYUm() {
        return pixelSizeYUm;
    }

    public double heightUm(int row, int col) {
        return heightsUm[row * cols + col];
    }

    /** A copy of the row-major heights. */
    public double[] heightsUm() {
        return heightsUm.clone();
    }

    public double meanUm() {
        double sum = 0;
        for (double h : heightsUm) {
            sum += h;
        }
        return sum / heightsUm.length;
    }

    /** The field with its mean removed, as the thesis' precompute does before the transform. */
    public HeightField meanSubtracted() {
        double mean = meanUm();
        double[] out = new double[heightsUm.length];
        for (int i = 0; i < out.length; i++) {
            out[i] = heightsUm[i] - mean;
        }
        return new HeightField(rows, cols, out, pixelSizeXUm, pixelSizeYUm);
    }

    /** max |h|: with the wavenumber this bounds the phase k |w| h of every sample (Taylor bound, 001 sec. 3.3.3). */
    public double maxAbsHeightUm() {
        double m = 0;
        for (double h : heightsUm) {
            m = Math.max(m, Math.abs(h));
        }
        return m;
    }

    public double minHeightUm() {
        double m = Double.POSITIVE_INFINITY;
        for (double h : heightsUm) {
            m = Math.min(m, h);
        }
        return m;
    }

    public double maxHeightUm() {
        double m = Double.NEGATIVE_INFINITY;
        for (double h : heightsUm) {
            m = Math.max(m, h);
        }
        return m;
    }

    /** Patch extent along x (columns) in micrometres: the period T of the DFT's implied replication. */
    public double widthUm() {
        return cols * pixelSizeXUm;
    }

    /** Patch extent along y (rows) in micrometres. */
    public double heightExtentUm() {
        return rows * pixelSizeYUm;
    }

    /**
     * SHA-256 over the grid size, pixel sizes and heights (little-endian doubles): the identity of a patch
     * for the precompute cache. Two fields with equal hashes give identical DFT terms.
     */
    public String contentSha256() {
        try {
            MessageDigest digest = MessageDigest.getInstance("SHA-256");
            ByteBuffer header = ByteBuffer.allocate(4 + 4 + 8 + 8).order(ByteOrder.LITTLE_ENDIAN);
            header.putInt(rows).putInt(cols).putDouble(pixelSizeXUm).putDouble(pixelSizeYUm);
            digest.update(header.array());
            ByteBuffer body = ByteBuffer.allocate(8 * 4096).order(ByteOrder.LITTLE_ENDIAN);
            for (double h : heightsUm) {
                if (!body.hasRemaining()) {
                    digest.update(body.array(), 0, body.position());
                    body.clear();
                }
                body.putDouble(h);
            }
            digest.update(body.array(), 0, body.position());
            return HexFormat.of().formatHex(digest.digest());
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every Java runtime", e);
        }
    }
}
