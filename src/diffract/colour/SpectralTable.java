package diffract.colour;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * A spectral function sampled on a uniform wavelength grid (nm), read from one column of a CSV table such as
 * the CIE tables under {@code /assets/colour/}. Between nodes it interpolates linearly (what CIE 15:2004
 * recommends for the D-series illuminants, and what pbrt-v4's {@code PiecewiseLinearSpectrum} does);
 * outside the tabulated range it is 0. Immutable.
 *
 * <p>CSV format: lines starting with {@code #} are comments, the first other line names the columns
 * (the first column is the wavelength in nm), then one row of numbers per node.
 */
public final class SpectralTable {
    // A grid is "uniform" if every node lies this fraction of a step from first + i * step.
    private static final double GRID_TOLERANCE_STEPS = 1e-9;

    private final double firstNm;
    private final double stepNm;
    private final double lastNm;
    private final double[] values;

    private SpectralTable(double firstNm, double stepNm, double[] values) {
        this.firstNm = firstNm;
        this.stepNm = stepNm;
        this.values = values;
        this.lastNm = firstNm + (values.length - 1) * stepNm;
    }

    /**
     * A table with {@code values[i]} at {@code firstNm + i * stepNm}.
     *
     * @throws IllegalArgumentException for fewer than 2 values, a non-positive step or a non-finite number
     */
    public static SpectralTable uniform(double firstNm, double stepNm, double[] values) {
        if (values.length < 2) {
            throw new IllegalArgumentException("a spectral table needs at least 2 nodes, got " + values.length);
        }
        if (!Double.isFinite(firstNm) || !(stepNm > 0) || !Double.isFinite(stepNm)) {
            throw new IllegalArgumentException("bad grid: first " + firstNm + " nm, step " + stepNm + " nm");
        }
        for (int i = 0; i < values.length; i++) {
            if (!Double.isFinite(values[i])) {
                throw new IllegalArgumentException("non-finite value " + values[i] + " at node " + i);
            }
        }
        return new SpectralTable(firstNm, stepNm, values.clone());
    }

    /**
     * Reads column {@code column} of the CSV classpath resource {@code resourcePath}
     * (e.g. {@code "/assets/colour/cie1931_2deg_cmf_1nm.csv"}, {@code "ybar"}).
     *
     * @throws IllegalArgumentException if the resource is missing or malformed, or has no such column
     */
    public static SpectralTable fromCsvResource(String resourcePath, String column) {
        try (InputStream in = SpectralTable.class.getResourceAsStream(resourcePath)) {
            if (in == null) {
                throw new IllegalArgumentException("classpath resource not found: " + resourcePath);
            }
            return fromCsv(new InputStreamReader(in, StandardCharsets.UTF_8), column, resourcePath);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + resourcePath, e);
        }
    }

    static SpectralTable fromCsv(Reader reader, String column, String sourceName) throws IOException {
        BufferedReader lines = new BufferedReader(reader);
        int columnIndex = -1;
        List<double[]> rows = new ArrayList<>();
        int lineNumber = 0;
        for (String line = lines.readLine(); line != null; line = lines.readLine()) {
            lineNumber++;
            String trimmed = line.strip();
            if (trimmed.isEmpty() || trimmed.startsWith("#")) {
                continue;
            }
            String[] cells = trimmed.split(",", -1);
            if (columnIndex < 0) {
                columnIndex = indexOf(cells, column);
                if (columnIndex < 1) {
                    throw new IllegalArgumentException(sourceName + ": no data column '" + column
                            + "' in header '" + trimmed + "'");
                }
                continue;
            }
            if (cells.length <= columnIndex) {
                throw new IllegalArgumentException(sourceName + ":" + lineNumber + ": too few columns");
            }
            try {
                double lambdaNm = Double.parseDouble(cells[0].strip());
                rows.add(new double[] {lambdaNm, Double.parseDouble(cells[columnIndex].strip())});
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(sourceName + ":" + lineNumber + ": not a number: " + trimmed, e);
            }
        }
        if (rows.size() < 2) {
            throw new IllegalArgumentException(sourceName + ": needs at least 2 data rows, has " + rows.size());
        }
        double first = rows.get(0)[0];
        double step = rows.get(1)[0] - first;
        double[] values = new double[rows.size()];
        for (int i = 0; i < values.length; i++) {
            double expectedNm = first + i * step;
            if (!(Math.abs(rows.get(i)[0] - expectedNm) <= GRID_TOLERANCE_STEPS * step)) {
                throw new IllegalArgumentException(sourceName + ": wavelengths are not a uniform increasing grid at "
                        + rows.get(i)[0] + " nm (expected " + expectedNm + " nm)");
            }
            values[i] = rows.get(i)[1];
        }
        return uniform(first, step, values);
    }

    private static int indexOf(String[] cells, String name) {
        for (int i = 0; i < cells.length; i++) {
            if (cells[i].strip().equals(name)) {
                return i;
            }
        }
        return -1;
    }

    /** The value at {@code lambdaNm}, linearly interpolated; 0 outside [firstNm, lastNm]; NaN for NaN. */
    public double at(double lambdaNm) {
        if (lambdaNm < firstNm || lambdaNm > lastNm) {
            return 0;
        }
        double t = (lambdaNm - firstNm) / stepNm;
        int i = (int) t;
        if (i >= values.length - 1) {
            return values[values.length - 1];
        }
        double fraction = t - i;
        // v_i + f (v_{i+1} - v_i) returns the node value exactly when lambda is on a node.
        return values[i] + fraction * (values[i + 1] - values[i]);
    }

    public double firstNm() {
        return firstNm;
    }

    public double lastNm() {
        return lastNm;
    }

    public double stepNm() {
        return stepNm;
    }

    public int nodeCount() {
        return values.length;
    }
}
