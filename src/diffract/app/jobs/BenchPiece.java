package diffract.app.jobs;

import diffract.bench.BenchConfig;
import diffract.bench.BenchResult;
import diffract.bench.MapError;
import diffract.jrtr.contexts.GLInfo;
import diffract.util.UserInputException;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * What a piece of a bench sweep measured ({@code bench --tile I/N}), in its manifest: one row per configuration it
 * measured, with every number exact (Java's shortest text that reads back as the same double, not the CSV's six
 * digits), so that merge writes results.csv and the tables from the same doubles one run has; the machine line and
 * the OpenGL the piece ran on.
 *
 * @param rows    per measured configuration: "ms_per_frame deltaE_mean deltaE_p95 deltaE_disk_mean lit_pixels KEY",
 *                KEY being {@link BenchConfig#key()}; configurations the variant refused have no row
 * @param machine the piece's machine line (machine.txt)
 * @param gl      the OpenGL of its last configuration, as {@link GLInfo}'s components in order; empty if none ran
 */
public record BenchPiece(List<String> rows, String machine, List<String> gl) {
    public static BenchPiece of(List<BenchResult> results, String machine, GLInfo gl) {
        List<String> rows = new ArrayList<>();
        for (BenchResult r : results) {
            MapError e = r.error();
            rows.add(String.join(" ", Double.toString(r.msPerFrame()), Double.toString(e.mean()),
                    Double.toString(e.p95()), Double.toString(e.diskMean()), Integer.toString(e.litPixels()),
                    r.config().key()));
        }
        List<String> glText = gl == null ? List.of() : List.of(gl.version(), gl.renderer(), gl.vendor(),
                gl.glslVersion(), Boolean.toString(gl.coreProfile()), gl.platform() == null ? "" : gl.platform());
        return new BenchPiece(rows, machine, glText);
    }

    /** The rows as results of the configurations they name ({@code configs}: the piece's, by key). */
    public List<BenchResult> results(Map<String, BenchConfig> configs, String piece) {
        List<BenchResult> out = new ArrayList<>();
        for (String row : rows) {
            String[] f = row.split(" ", 6);
            BenchConfig c = f.length == 6 ? configs.get(f[5]) : null;
            if (c == null) {
                throw new UserInputException("merge: bench piece " + piece + " holds a row of a configuration that is "
                        + "not its own in this sweep ('" + row + "'): compute it again with this diffract");
            }
            try {
                out.add(new BenchResult(c, Double.parseDouble(f[0]), new MapError(Double.parseDouble(f[1]),
                        Double.parseDouble(f[2]), Double.parseDouble(f[3]), Integer.parseInt(f[4]))));
            } catch (NumberFormatException e) {
                throw new UserInputException("merge: bench piece " + piece + " holds a damaged row ('" + row
                        + "'): compute it again");
            }
        }
        return out;
    }

    /** The OpenGL the piece ran on; null when it measured nothing. */
    public GLInfo glInfo() {
        if (gl.isEmpty()) {
            return null;
        }
        if (gl.size() != 6) {
            throw new UserInputException("merge: a bench piece's OpenGL is damaged (" + gl + "): compute it again");
        }
        return new GLInfo(gl.get(0), gl.get(1), gl.get(2), gl.get(3), Boolean.parseBoolean(gl.get(4)),
                gl.get(5).isEmpty() ? null : gl.get(5));
    }
}
