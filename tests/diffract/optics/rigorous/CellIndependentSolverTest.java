package diffract.optics.rigorous;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The 2-D Fourier modal method against meent 0.13.2 ({@code tests/python/cell_crosscheck.py} through the python3 on
 * the PATH), as {@link IndependentSolverTest} checks the 1-D one. Both are given the same staircase of pixel masks and
 * the same rectangular set of harmonics; meent's exact Fourier series of the raster is asked for Laurent's rule in
 * every component (the cell solver's formulation): every reflected order that carries at least 5 % of the reflected
 * power (unpolarised) agrees to 1 %. Against meent's own Li's rules for crossed gratings the difference (Laurent's
 * slower convergence) is printed, not held. Skips where python3 or meent is missing.
 */
@Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a cross-check against other solvers: a long test
class CellIndependentSolverTest {
    static final Path SCRIPT = Path.of("tests", "python", "cell_crosscheck.py");

    record Incidence(double thetaDeg, double phiDeg) {
        String key() {
            return thetaDeg + "_" + phiDeg;
        }
    }

    record Case(String key, CellRelief relief, int layers, double lambdaUm, int maxOrder, List<Incidence> incidences) {
        Cell cell() {
            return Cell.of(relief, layers, ComplexIndex.KERATIN);
        }
    }

    static final List<Case> CASES = List.of(
            new Case("pillar", CellFourierModalMethodTest.pillar(1.0, 1.2, 8, 8, 3, 0.3), 1, 0.5, 4,
                    List.of(new Incidence(0, 0), new Incidence(30, 0), new Incidence(30, 40))),
            new Case("bump", CellFourierModalMethodTest.bump(1.1, 1.1, 12, 12, 0.25), 4, 0.45, 3,
                    List.of(new Incidence(20, 30))));

    @Test
    void agreesWithMeentOnSmallCells() throws Exception {
        ObjectMapper json = new ObjectMapper();
        ArrayNode cases = json.createArrayNode();
        for (Case c : CASES) {
            ObjectNode o = cases.addObject();
            o.put("key", c.key());
            o.put("periodXUm", c.relief().periodXUm());
            o.put("periodYUm", c.relief().periodYUm());
            o.put("cols", c.relief().cols());
            o.put("rows", c.relief().rows());
            o.putArray("index").add(ComplexIndex.KERATIN.n()).add(ComplexIndex.KERATIN.k());
            o.put("lambdaUm", c.lambdaUm());
            o.put("maxOrder", c.maxOrder());
            ArrayNode slabs = o.putArray("slabs");
            for (CellSlab s : c.cell().slabs()) {
                ObjectNode slab = slabs.addObject();
                slab.put("thicknessUm", s.thicknessUm());
                ArrayNode mask = slab.putArray("mask");
                for (boolean b : s.mask()) {
                    mask.add(b ? 1 : 0);
                }
            }
            ArrayNode incidences = o.putArray("incidences");
            for (Incidence i : c.incidences()) {
                incidences.addObject().put("thetaDeg", i.thetaDeg()).put("phiDeg", i.phiDeg());
            }
        }
        Path file = Files.createTempFile("cell-crosscheck", ".json");
        JsonNode results;
        try {
            Files.writeString(file, json.writeValueAsString(cases));
            Process p;
            try {
                p = new ProcessBuilder("python3", SCRIPT.toString(), file.toString())
                        .redirectError(ProcessBuilder.Redirect.DISCARD).start();
            } catch (IOException e) {
                assumeTrue(false, "python3 is not on the PATH: the independent solver runs in Python");
                return;
            }
            p.getOutputStream().close();
            BufferedReader lines = new BufferedReader(new InputStreamReader(p.getInputStream(),
                    StandardCharsets.UTF_8));
            String first = lines.readLine();
            JsonNode versions = first == null ? null : json.readTree(first).get("versions");
            if (versions == null || !versions.hasNonNull("meent")) {
                p.destroy();
                assumeTrue(false, "meent is not installed for python3 (pip install meent==0.13.2)");
            }
            String second = lines.readLine();
            assertTrue(p.waitFor(600, TimeUnit.SECONDS), "meent did not finish in 10 minutes");
            assertEquals(0, p.exitValue(), "cell_crosscheck.py failed");
            results = json.readTree(second).get("results");
        } finally {
            Files.deleteIfExists(file);
        }
        int compared = 0;
        for (Case c : CASES) {
            for (Incidence i : c.incidences()) {
                double t = Math.toRadians(i.thetaDeg());
                double f = Math.toRadians(i.phiDeg());
                CellEfficiencies ours = CellFourierModalMethod.solve(c.cell(), c.lambdaUm(), Math.sin(t) * Math.cos(f),
                        Math.sin(t) * Math.sin(f), c.maxOrder(), c.maxOrder());
                JsonNode laurent = results.get(c.key()).get(i.key()).get("laurent");
                JsonNode li = results.get(c.key()).get(i.key()).get("li");
                int m = c.maxOrder();
                double total = ours.totalReflected();
                double worst = 0;
                double worstLi = 0;
                for (int q = -m; q <= m; q++) {
                    for (int p = -m; p <= m; p++) {
                        double mine = ours.reflected(p, q);
                        double theirs = laurent.get(q + m).get(p + m).asDouble();
                        double liValue = li.get(q + m).get(p + m).asDouble();
                        if (Math.max(mine, theirs) < 0.05 * total) {
                            continue;
                        }
                        compared++;
                        double d = Math.abs(mine - theirs) / theirs;
                        worst = Math.max(worst, d);
                        worstLi = Math.max(worstLi, Math.abs(mine - liValue) / liValue);
                        assertEquals(theirs, mine, 0.01 * theirs, String.format(Locale.ROOT,
                                "order (%d, %d) of the %s at %s", p, q, c.key(), i.key()));
                    }
                }
                System.out.printf(Locale.ROOT, "%s at %s, M = %d: against meent (Laurent) %.2e, against meent's Li "
                        + "rules %.2e (orders >= 5 %% of R = %.5f)%n", c.key(), i.key(), m, worst, worstLi, total);
            }
        }
        assertTrue(compared >= CASES.size(), "orders compared: " + compared);
    }
}
