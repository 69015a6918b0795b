package diffract.bench;

import diffract.jrtr.contexts.GLInfo;
import diffract.optics.BrdfSettings;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;
import diffract.util.ImageFiles;
import diffract.util.UserInputException;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Collectors;

/**
 * The bench's results as {@code results.csv} (one row per configuration, read back for the calibration cache)
 * and as a markdown table. deltaE_mean and deltaE_p95 are CIEDE2000 over the lit pixels of the three maps
 * ({@link MapError}); deltaE_disk_mean over the whole unit disks; pareto says whether the row is on the Pareto
 * front of (ms_per_frame, deltaE_mean) of its patch and map size (errors of different sizes are not comparable).
 */
public final class ResultsTable {
    /** The measured columns; a results.csv with only these (no GL columns) still reads back. */
    static final List<String> MEASURED_COLUMNS = List.of("variant", "patch", "terms", "lambda_step_nm",
            "window_radius", "texture_format", "width", "height", "ms_per_frame", "deltaE_mean", "deltaE_p95",
            "deltaE_disk_mean", "lit_pixels", "coherence_length_um", "pareto", "taylor_tolerance");
    /**
     * Every column: the measured ones, then the OpenGL the row ran on (driver strings with their commas written as
     * semicolons, so that every row splits on commas).
     */
    public static final List<String> COLUMNS = java.util.stream.Stream.concat(MEASURED_COLUMNS.stream(),
            java.util.stream.Stream.of("gl_vendor", "gl_renderer", "gl_version", "gl_platform")).toList();

    private ResultsTable() {
    }

    public static String csvHeader() {
        return String.join(",", COLUMNS);
    }

    /** One row; {@code gl} is the OpenGL it was measured on (null: empty GL columns). */
    public static String csvRow(BenchResult r, boolean onFront, GLInfo gl) {
        return csvRow(r, onFront) + "," + glFields(gl);
    }

    /** The GL columns' values. */
    static String glFields(GLInfo gl) {
        return gl == null ? ",,," : String.join(",", field(gl.vendor()), field(gl.renderer()), field(gl.version()),
                field(gl.platform()));
    }

    private static String field(String driverText) {
        return driverText == null ? "" : driverText.replace(',', ';').replace('\n', ' ').replace('\r', ' ');
    }

    private static String csvRow(BenchResult r, boolean onFront) {
        BenchConfig c = r.config();
        BrdfSettings s = c.settings();
        return String.join(",", s.variant().label(), c.patch(), Integer.toString(s.taylor().highestOrder()),
                Csv.number(s.spectral().lambdaStepNm()), c.windowRadiusLabel(), c.textureFormat(),
                Integer.toString(c.sizePx()), Integer.toString(c.sizePx()), Csv.number(r.msPerFrame()),
                Csv.number(r.error().mean()), Csv.number(r.error().p95()), Csv.number(r.error().diskMean()),
                Integer.toString(r.error().litPixels()), Csv.number(s.illumination().coherenceLengthUm()),
                Boolean.toString(onFront), Csv.number(s.taylor().tolerance()));
    }

    /** The rows on the Pareto front of one patch at one map size. */
    public static List<BenchResult> front(List<BenchResult> results, String patch, int sizePx) {
        List<BenchResult> ofPatch = results.stream()
                .filter(r -> r.config().patch().equals(patch) && r.config().sizePx() == sizePx).toList();
        return ParetoFront.of(ofPatch, BenchResult::msPerFrame, BenchResult::deltaEMean);
    }

    /** The rows on the front of their own patch and size. */
    public static List<BenchResult> onAnyFront(List<BenchResult> results) {
        List<BenchResult> onFront = new ArrayList<>();
        results.stream().map(r -> r.config().patch()).distinct().forEach(p -> results.stream()
                .map(r -> r.config().sizePx()).distinct().forEach(size -> onFront.addAll(front(results, p, size))));
        return onFront;
    }

    /** The size most configurations were measured at (the sweep's; the others are single extra points). */
    public static int mainSize(List<BenchResult> results) {
        return results.stream().collect(Collectors.groupingBy(r -> r.config().sizePx(), Collectors.counting()))
                .entrySet().stream().max(Map.Entry.comparingByValue()).map(Map.Entry::getKey).orElse(0);
    }

    public static void writeCsv(Path file, List<BenchResult> results) throws IOException {
        writeCsv(file, results, null);
    }

    /** Writes every row, measured on {@code gl}. */
    public static void writeCsv(Path file, List<BenchResult> results, GLInfo gl) throws IOException {
        String text = csv(results, gl);
        ImageFiles.writeAtomically(file, raw -> raw.write(text.getBytes(StandardCharsets.UTF_8)));
    }

    /** The text of a results.csv: the header and every row, measured on {@code gl}. */
    public static String csv(List<BenchResult> results, GLInfo gl) {
        List<BenchResult> onFront = onAnyFront(results);
        StringBuilder out = new StringBuilder(csvHeader()).append(System.lineSeparator());
        for (BenchResult r : results) {
            out.append(csvRow(r, onFront.contains(r), gl)).append(System.lineSeparator());
        }
        return out.toString();
    }

    /** Reads a results.csv written by {@link #writeCsv}; the settings not in the file come from {@code base}. */
    public static List<BenchResult> readCsv(Path file, BrdfSettings base) throws IOException {
        return parseCsv(file.toString(), Files.readAllLines(file, StandardCharsets.UTF_8), base);
    }

    /**
     * The rows of a results.csv's lines ({@code source} names it in the refusal of another version's header).
     *
     * @throws RuntimeException when a row does not parse (a bad number, a short row)
     */
    public static List<BenchResult> parseCsv(String source, List<String> lines, BrdfSettings base) {
        if (lines.isEmpty() || !(lines.get(0).equals(csvHeader())
                || lines.get(0).equals(String.join(",", MEASURED_COLUMNS)))) {
            throw new UserInputException(source + " is not a results.csv of this version (header differs)");
        }
        List<BenchResult> results = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            String[] f = line.split(",", -1);
            boolean automaticWindow = f[4].equals("auto");
            BrdfSettings s = base.toBuilder().variant(Variant.parse(f[0])).highestOrder(Integer.parseInt(f[2]))
                    .lambdaStepNm(Double.parseDouble(f[3]))
                    .windowRadius(automaticWindow ? base.window().radius() : Integer.parseInt(f[4]))
                    .automaticWindowRadius(automaticWindow).taylorTolerance(Double.parseDouble(f[15]))
                    .termFormat(TermFormat.valueOf(f[5].toUpperCase(Locale.ROOT)))
                    .expansion(SweepPlan.expansionOf(Variant.parse(f[0]))).build();
            BenchConfig c = new BenchConfig(f[1], s, Integer.parseInt(f[6]));
            results.add(new BenchResult(c, Double.parseDouble(f[8]), new MapError(parse(f[9]), parse(f[10]),
                    parse(f[11]), Integer.parseInt(f[12]))));
        }
        return results;
    }

    private static double parse(String text) {
        return text.equals("nan") ? Double.NaN : Double.parseDouble(text);
    }

    /** A markdown table, by patch, with a column that marks the Pareto-front rows. */
    public static String markdown(List<BenchResult> results) {
        return markdown(results, false);
    }

    /** @param frontOnly only the rows on the Pareto front of their patch and size */
    public static String markdown(List<BenchResult> results, boolean frontOnly) {
        List<BenchResult> onFront = onAnyFront(results);
        StringBuilder b = new StringBuilder();
        b.append("| patch | variant | N | step nm | R | Taylor tolerance | format | size | ms/frame | CIEDE2000 mean | p95 |"
                + " disk mean | Pareto |\n");
        b.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        List<String> patches = results.stream().map(r -> r.config().patch()).distinct().toList();
        for (String patch : patches) {
            for (BenchResult r : results) {
                if (!r.config().patch().equals(patch) || frontOnly && !onFront.contains(r)) {
                    continue;
                }
                BenchConfig c = r.config();
                BrdfSettings s = c.settings();
                b.append(String.format(Locale.ROOT, "| %s | %s | %d | %s | %s | %s | %s | %d | %.2f | %.3f | %.3f | %.3f | %s |%n",
                        patch, s.variant().label(), s.taylor().highestOrder(), Csv.number(s.spectral().lambdaStepNm()),
                        c.windowRadiusLabel(), Csv.number(s.taylor().tolerance()), c.textureFormat(), c.sizePx(), r.msPerFrame(), r.error().mean(), r.error().p95(),
                        r.error().diskMean(), onFront.contains(r) ? "**yes**" : ""));
            }
        }
        return b.toString();
    }
}
