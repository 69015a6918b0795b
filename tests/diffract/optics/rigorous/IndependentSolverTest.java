package diffract.optics.rigorous;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import diffract.util.TestReport;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The Fourier modal method against independent, well-kept implementations of it, run by
 * {@code tests/python/rigorous_crosscheck.py} through the python3 on the PATH: meent 0.13.2 and nannos 2.6.5, both
 * with Li's factorisation rules. Each solves the same staircase: the relief's slabs as {@link Staircase} cuts them,
 * with every edge rounded to a raster of {@link #RASTER} cells per period, and diffract solves that rounded
 * staircase too, so the solvers differ only in how they solve it. Every reflected order that carries at least 5 %
 * of the reflected power (for s or p light, in diffract's result or the other's) agrees to 1 %; an independent
 * result counts only where it conserves energy (R + T = 1 to 1e-6 on a lossless grating): meent's transfer
 * matrices lose that on wide periods with many orders, where nannos stands in.
 *
 * <p>inkstone 0.3.15 joins when {@code -Ddiffract.crosscheck.solvers=meent,nannos,inkstone} asks for it
 * (docs/measurements/rigorous-crosscheck.sh): it is reported but not held to 1 %, since it takes Laurent's rule for every field
 * component, under which p converges slowly with the harmonics (about 1 % off at M = 30).
 *
 * <p>Skips where python3 or meent is missing ({@code .ci/install-deps --tests} installs them). The cases' table goes
 * to {@code target/test-reports/IndependentSolverTest.txt}.
 */
@Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a cross-check against other solvers: a long test
class IndependentSolverTest {
    static final Path SCRIPT = Path.of("tests", "python", "rigorous_crosscheck.py");
    /** Cells per period of the raster every solver's staircase is drawn on. */
    static final int RASTER = 8192;
    /** An order is compared when it carries at least this share of the reflected power. */
    static final double SHARE = 0.05;
    /** The largest relative difference allowed on those orders. */
    static final double AGREEMENT = 0.01;
    /** How far from 1 an independent lossless R + T may be for its result to count. */
    static final double ENERGY = 1e-6;
    /** The solvers held to {@link #AGREEMENT} (Li's rules). */
    static final List<String> CHECKED = List.of("meent", "nannos");
    static final List<String> ALL = List.of("meent", "nannos", "inkstone");

    /** Light along (sin theta cos phi, sin theta sin phi) in the grating's frame, phi from the grating vector. */
    record Incidence(double thetaDeg, double phiDeg) {
        String key() {
            return thetaDeg + "_" + phiDeg;
        }

        String label() {
            return phiDeg == 0 ? String.format(Locale.ROOT, "%.0f°", thetaDeg)
                    : String.format(Locale.ROOT, "%.0f°, azimuth %.0f°", thetaDeg, phiDeg);
        }

        double alpha0() {
            return Math.sin(Math.toRadians(thetaDeg)) * Math.cos(Math.toRadians(phiDeg));
        }

        double beta() {
            return Math.sin(Math.toRadians(thetaDeg)) * Math.sin(Math.toRadians(phiDeg));
        }
    }

    /** A relief of one material on a half-space of it, cut into {@code layers} slabs, solved on M harmonics. */
    record Case(String key, Profile profile, ComplexIndex index, double lambdaUm, int layers, int maxOrder,
                List<Incidence> incidences) {
        /** The staircase with every edge on the raster: what all the solvers are given. */
        Grating grating() {
            return new Grating(profile.periodUm(), rastered(profile, layers), index, index);
        }

        String description() {
            return String.format(Locale.ROOT, "%s, n = %s, %.0f nm, %d slabs, M = %d", profile.description(), index,
                    lambdaUm * 1e3, layers, maxOrder);
        }
    }

    static final List<Case> CASES = List.of(
            new Case("sinusoid", Profile.sinusoid(1.0, 0.3), ComplexIndex.KERATIN, 0.55, 12, 30,
                    List.of(new Incidence(0, 0), new Incidence(30, 0), new Incidence(60, 0))),
            // rising over 80 % of the period: its orders m and -m differ, so the orders' sign is checked too
            new Case("triangle", Profile.triangle(1.0, 0.3, 0.8), ComplexIndex.KERATIN, 0.55, 12, 30,
                    List.of(new Incidence(0, 0), new Incidence(30, 0), new Incidence(60, 0), new Incidence(30, 40))),
            new Case("absorbing sinusoid", Profile.sinusoid(1.0, 0.3), new ComplexIndex(1.56, 0.05), 0.55, 12, 30,
                    List.of(new Incidence(30, 0), new Incidence(30, 40))),
            // 11 orders propagate back into the air, 17 into the keratin: meent's transfer matrices lose energy
            // (R + T = 1.005 for s, 1.013 for p) and nannos stands in
            new Case("wide triangle", Profile.triangle(2.5, 0.4, 0.8), ComplexIndex.KERATIN, 0.45, 16, 40,
                    List.of(new Incidence(75, 120))));

    /** The slabs of {@code profile} with their edges moved to the nearest raster line. */
    static List<Slab> rastered(Profile profile, int layers) {
        List<Slab> out = new ArrayList<>();
        for (Slab slab : Staircase.of(profile, layers)) {
            out.add(new Slab(slab.thicknessUm(), Arrays.stream(cells(slab)).mapToDouble(c -> c / (double) RASTER)
                    .toArray()));
        }
        return out;
    }

    static long[] cells(Slab slab) {
        return Arrays.stream(slab.edges()).mapToLong(e -> Math.round(e * RASTER)).toArray();
    }

    /**
     * The solvers' results, results.get(case).get(incidence).get(solver) as the script wrote them, and diffract's,
     * with the seconds each side took (diffract's solved while the script ran).
     */
    record Run(List<String> solvers, Map<String, String> versions, JsonNode results, double seconds,
               Map<String, OrderEfficiencies> ours, double oursSeconds) {
        JsonNode result(Case c, Incidence i, String solver) {
            return results.path(c.key()).path(i.key()).path(solver);
        }

        OrderEfficiencies ours(Case c, Incidence i) {
            return ours.get(c.key() + " " + i.key());
        }
    }

    private static Run run;
    private static String skipped;

    /** Runs the script once for all the cases (skips the caller where python3 or meent is missing). */
    static synchronized Run run() throws Exception {
        if (run == null && skipped == null) {
            skipped = start();
        }
        assumeTrue(skipped == null, skipped);
        return run;
    }

    /** Null when the run went ahead, else why it was skipped. */
    private static String start() throws Exception {
        ObjectMapper json = new ObjectMapper();
        String asked = System.getProperty("diffract.crosscheck.solvers", "meent,nannos");
        Path cases = Files.createTempFile("rigorous-crosscheck", ".json");
        Path errors = Files.createTempFile("rigorous-crosscheck", ".err");
        try {
            Files.writeString(cases, json.writeValueAsString(casesJson(json)));
            long start = System.nanoTime();
            Process p;
            try {
                p = new ProcessBuilder("python3", SCRIPT.toString(), "--solvers", asked, "--progress",
                        cases.toString()).redirectError(errors.toFile()).start();
            } catch (IOException e) {
                return "python3 is not on the PATH: the independent solvers run in Python";
            }
            p.getOutputStream().close();
            BufferedReader lines = new BufferedReader(new InputStreamReader(p.getInputStream(),
                    StandardCharsets.UTF_8));
            String first = lines.readLine();
            JsonNode versions = first == null ? null : json.readTree(first).get("versions");
            if (versions == null || !versions.hasNonNull("meent")) {
                p.destroy();
                p.waitFor(60, TimeUnit.SECONDS);
                return "meent is not installed for python3 (pip install meent==0.13.2; .ci/install-deps --tests "
                        + "installs it): " + (first == null ? read(errors).strip()
                        : json.readTree(first).path("missing").path("meent").asText(""));
            }
            // diffract solves the cases while the script does
            Map<String, OrderEfficiencies> ours = new LinkedHashMap<>();
            long oursStart = System.nanoTime();
            for (Case c : CASES) {
                for (Incidence i : c.incidences()) {
                    ours.put(c.key() + " " + i.key(), ours(c, i));
                }
            }
            double oursSeconds = (System.nanoTime() - oursStart) * 1e-9;
            String second = lines.readLine();
            if (!p.waitFor(600, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                fail("the independent solvers did not finish in 10 minutes");
            }
            double seconds = (System.nanoTime() - start) * 1e-9;
            assertEquals(0, p.exitValue(), () -> "rigorous_crosscheck.py failed: " + read(errors));
            List<String> solvers = new ArrayList<>();
            Map<String, String> found = new LinkedHashMap<>();
            for (String s : ALL) {
                if (asked.contains(s) && versions.hasNonNull(s)) {
                    solvers.add(s);
                    found.put(s, versions.get(s).asText());
                }
            }
            JsonNode document = json.readTree(second);
            run = new Run(solvers, found, document.get("results"), seconds, ours, oursSeconds);
        } finally {
            Files.deleteIfExists(cases);
            Files.deleteIfExists(errors);
        }
        return null;
    }

    private static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            return "(unreadable: " + e.getMessage() + ")";
        }
    }

    /** The cases as the script reads them: the rastered slabs' cells, the incidences in degrees. */
    static ArrayNode casesJson(ObjectMapper json) {
        ArrayNode cases = json.createArrayNode();
        for (Case c : CASES) {
            ObjectNode o = cases.addObject();
            o.put("key", c.key());
            o.put("periodUm", c.profile().periodUm());
            o.put("lambdaUm", c.lambdaUm());
            o.put("maxOrder", c.maxOrder());
            o.put("raster", RASTER);
            o.putArray("index").add(c.index().n()).add(c.index().k());
            ArrayNode slabs = o.putArray("slabs");
            for (Slab s : Staircase.of(c.profile(), c.layers())) {
                ObjectNode slab = slabs.addObject();
                slab.put("thicknessUm", s.thicknessUm());
                ArrayNode cells = slab.putArray("cells");
                for (long cell : cells(s)) {
                    cells.add(cell);
                }
            }
            ArrayNode incidences = o.putArray("incidences");
            for (Incidence i : c.incidences()) {
                incidences.addObject().put("key", i.key()).put("thetaDeg", i.thetaDeg()).put("phiDeg", i.phiDeg());
            }
        }
        return cases;
    }

    /** The worst relative difference of {@code theirs} from {@code ours} over the orders that carry SHARE. */
    record Comparison(double worst, int worstOrder, List<Integer> orders) {
    }

    /** Orders -M..M at indices 0..2M in both. */
    static Comparison compare(double[] ours, double[] theirs) {
        int m = (ours.length - 1) / 2;
        double oursTotal = Arrays.stream(ours).sum();
        double theirsTotal = Arrays.stream(theirs).sum();
        double worst = 0;
        int worstOrder = 0;
        List<Integer> orders = new ArrayList<>();
        for (int i = 0; i < ours.length; i++) {
            if (ours[i] >= SHARE * oursTotal || theirs[i] >= SHARE * theirsTotal) {
                orders.add(i - m);
                double d = Math.abs(theirs[i] - ours[i]) / ours[i];
                if (!(d <= worst)) {
                    worst = d;
                    worstOrder = i - m;
                }
            }
        }
        return new Comparison(worst, worstOrder, orders);
    }

    static double[] array(JsonNode values) {
        double[] out = new double[values.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = values.get(i).asDouble();
        }
        return out;
    }

    static OrderEfficiencies ours(Case c, Incidence i) {
        return FourierModalMethod.solve(c.grating(), c.lambdaUm(), i.alpha0(), i.beta(), c.maxOrder());
    }

    /** Whether an independent result counts: it ran, and conserves energy where the grating is lossless. */
    static String invalid(Case c, JsonNode result) {
        if (result.isMissingNode()) {
            return "not run";
        }
        if (result.has("error")) {
            return result.get("error").asText();
        }
        if (!c.index().absorbs()) {
            double s = result.get("energy").get(0).asDouble();
            double p = result.get("energy").get(1).asDouble();
            if (!(Math.abs(s - 1) <= ENERGY && Math.abs(p - 1) <= ENERGY)) {
                return String.format(Locale.ROOT, "R + T = %.7f (s), %.7f (p)", s, p);
            }
        }
        return null;
    }

    @TestFactory
    Stream<DynamicTest> reflectedOrdersAgreeWithIndependentSolvers() throws Exception {
        Run r = run();
        List<DynamicTest> tests = new ArrayList<>();
        StringBuilder table = new StringBuilder();
        StringBuilder energy = new StringBuilder();
        double[] worst = new double[ALL.size()];
        for (Case c : CASES) {
            for (Incidence i : c.incidences()) {
                OrderEfficiencies ours = r.ours(c, i);
                tests.add(DynamicTest.dynamicTest(c.key() + " at " + i.label(), () -> check(r, c, i, ours)));
                report(r, c, i, ours, table, energy, worst);
            }
        }
        StringBuilder head = new StringBuilder();
        head.append(String.format(Locale.ROOT, "Solvers: %s; raster %d cells per period.%n%n", r.versions(), RASTER));
        head.append("Cases:\n\n");
        for (Case c : CASES) {
            head.append("- ").append(c.key()).append(": ").append(c.description()).append('\n');
        }
        head.append("\n| case | light | pol | order | ours |");
        for (String s : r.solvers()) {
            head.append(' ').append(s).append(" |");
        }
        for (String s : r.solvers()) {
            head.append(' ').append(s).append(" - ours |");
        }
        head.append("\n|---|---|---|---|---|").append("---|".repeat(2 * r.solvers().size())).append('\n');
        List<String> worstOf = new ArrayList<>();
        for (String s : r.solvers()) {
            worstOf.add(String.format(Locale.ROOT, "%s %.1e", s, worst[ALL.indexOf(s)]));
        }
        String summary = String.format(Locale.ROOT, "%nWorst relative difference on the orders compared, results "
                + "that conserve energy (or absorb) only: %s.%n%nSeconds: the Python solvers %.1f (with their "
                + "imports), diffract %.1f (at the same time, on the same cores).%n", String.join(", ", worstOf),
                r.seconds(), r.oursSeconds());
        StringBuilder energyHead = new StringBuilder("\n| case | light |");
        for (String s : r.solvers()) {
            energyHead.append(' ').append(s).append(" R + T (s, p); seconds |");
        }
        energyHead.append("\n|---|---|").append("---|".repeat(r.solvers().size())).append('\n');
        TestReport.line(IndependentSolverTest.class, head.toString() + table + summary + energyHead + energy);
        return tests.stream();
    }

    private static void check(Run r, Case c, Incidence i, OrderEfficiencies ours) {
        List<String> counted = new ArrayList<>();
        List<String> rejected = new ArrayList<>();
        for (String solver : CHECKED) {
            if (!r.solvers().contains(solver)) {
                rejected.add(solver + ": not installed");
                continue;
            }
            JsonNode result = r.result(c, i, solver);
            String why = invalid(c, result);
            if (why != null) {
                rejected.add(solver + ": " + why);
                continue;
            }
            counted.add(solver);
            for (String pol : List.of("s", "p")) {
                double[] mine = pol.equals("s") ? ours.reflectedS() : ours.reflectedP();
                double[] theirs = array(result.get("R" + pol));
                assertEquals(mine.length, theirs.length, solver + " returns orders -M..M");
                Comparison k = compare(mine, theirs);
                assertFalse(k.orders().isEmpty());
                assertTrue(k.worst() <= AGREEMENT, () -> String.format(Locale.ROOT,
                        "%s at %s, %s: %s differs by %.2g %% on order %d (ours %.6g, %s %.6g); orders compared %s",
                        c.key(), i.label(), pol, solver, 100 * k.worst(), k.worstOrder(),
                        mine[k.worstOrder() + c.maxOrder()], solver, theirs[k.worstOrder() + c.maxOrder()],
                        k.orders()));
            }
        }
        if (counted.isEmpty()) {
            String why = c.key() + " at " + i.label() + ": no independent result to compare with (" + String.join("; ",
                    rejected) + ")";
            // a solver that is missing skips the case; solvers that ran and all lost energy fail it
            assumeTrue(CHECKED.stream().allMatch(r.solvers()::contains), why);
            fail(why);
        }
    }

    private static void report(Run r, Case c, Incidence i, OrderEfficiencies ours, StringBuilder table,
                               StringBuilder energy, double[] worst) {
        energy.append("| ").append(c.key()).append(" | ").append(i.label()).append(" |");
        for (String solver : r.solvers()) {
            JsonNode result = r.result(c, i, solver);
            if (result.has("error") || result.isMissingNode()) {
                energy.append(" ").append(result.path("error").asText("not run")).append(" |");
                continue;
            }
            String why = invalid(c, result);
            energy.append(String.format(Locale.ROOT, " %.9f, %.9f; %.1f%s |", result.get("energy").get(0).asDouble(),
                    result.get("energy").get(1).asDouble(), result.get("seconds").asDouble(),
                    why == null ? "" : " (not counted)"));
        }
        energy.append('\n');
        for (String pol : List.of("s", "p")) {
            double[] mine = pol.equals("s") ? ours.reflectedS() : ours.reflectedP();
            List<Integer> orders = new ArrayList<>();
            Map<String, double[]> theirs = new LinkedHashMap<>();
            for (String solver : r.solvers()) {
                JsonNode result = r.result(c, i, solver);
                if (result.has("R" + pol)) {
                    double[] values = array(result.get("R" + pol));
                    theirs.put(solver, values);
                    Comparison k = compare(mine, values);
                    for (int o : k.orders()) {
                        if (!orders.contains(o)) {
                            orders.add(o);
                        }
                    }
                    if (invalid(c, result) == null) {
                        int s = ALL.indexOf(solver);
                        worst[s] = Math.max(worst[s], k.worst());
                    }
                }
            }
            orders.sort(null);
            for (int o : orders) {
                int at = o + c.maxOrder();
                table.append(String.format(Locale.ROOT, "| %s | %s | %s | %d | %.6f |", c.key(), i.label(), pol, o,
                        mine[at]));
                for (String solver : r.solvers()) {
                    double[] v = theirs.get(solver);
                    table.append(v == null ? " - |" : String.format(Locale.ROOT, " %.6f |", v[at]));
                }
                for (String solver : r.solvers()) {
                    double[] v = theirs.get(solver);
                    table.append(v == null ? " - |" : String.format(Locale.ROOT, " %+.1e%s |",
                            (v[at] - mine[at]) / mine[at], invalid(c, r.result(c, i, solver)) == null ? "" : " *"));
                }
                table.append('\n');
            }
        }
    }

    /**
     * The comparison catches what it is meant to: a relief 5 % deeper than the one the other solver had, or the
     * orders' signs swapped on an asymmetric relief, miss by more than 1 %.
     */
    @Test
    void theComparisonCatchesADifferentGratingAndSwappedOrders() throws Exception {
        Run r = run();
        Case sinusoid = CASES.get(0);
        Incidence oblique = sinusoid.incidences().get(1);
        JsonNode meent = r.result(sinusoid, oblique, "meent");
        assertEquals(null, invalid(sinusoid, meent));
        Profile deeper = Profile.sinusoid(1.0, 0.3 * 1.05);
        OrderEfficiencies wrong = FourierModalMethod.solve(new Grating(1.0, rastered(deeper, sinusoid.layers()),
                sinusoid.index(), sinusoid.index()), sinusoid.lambdaUm(), oblique.alpha0(), oblique.beta(),
                sinusoid.maxOrder());
        Comparison k = compare(wrong.reflectedS(), array(meent.get("Rs")));
        assertTrue(k.worst() > AGREEMENT, "a 5 % deeper sinusoid differs by " + k.worst());

        Case triangle = CASES.get(1);
        Incidence normal = triangle.incidences().get(0);
        OrderEfficiencies ours = r.ours(triangle, normal);
        double[] mirrored = ours.reflectedS().clone();
        for (int a = 0, b = mirrored.length - 1; a < b; a++, b--) {
            double t = mirrored[a];
            mirrored[a] = mirrored[b];
            mirrored[b] = t;
        }
        JsonNode theirs = r.result(triangle, normal, "meent");
        assertTrue(compare(ours.reflectedS(), array(theirs.get("Rs"))).worst() <= AGREEMENT);
        Comparison swapped = compare(mirrored, array(theirs.get("Rs")));
        assertTrue(swapped.worst() > AGREEMENT, "the triangle's orders mirrored differ by " + swapped.worst());
        TestReport.printf(IndependentSolverTest.class, "%nThe comparison's own check: a 5 %% deeper sinusoid at %s "
                + "misses meent by %.1f %% (order %d, s); the triangle's orders mirrored at %s by %.0f %% (order %d).%n",
                oblique.label(), 100 * k.worst(), k.worstOrder(), normal.label(), 100 * swapped.worst(),
                swapped.worstOrder());
    }
}
