package diffract.bench;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.HeatMapChart;
import org.knowm.xchart.HeatMapChartBuilder;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The validity map's files: the table of every case (CSV, also what {@link diffract.optics.validity.ScalarValidity}
 * reads from {@code assets/validity/}), the heat maps of CIEDE2000 per relief (one panel per light angle, periods
 * across, depths up; XChart) and the Markdown that shows them with the tables of numbers.
 */
public final class ValidityReport {
    /** The CSV's columns. */
    public static final String HEADER = "relief,periodUm,depthUm,thetaDeg,deltaE,deltaEP95,deltaEStam,orderError,"
            + "orderErrorStam,litPixels";
    /** The colour classes of the heat maps: CIEDE2000 up to these bounds. */
    private static final double[] BOUNDS = {1, 3, 10, 1e9};
    private static final Color[] COLOURS = {new Color(40, 160, 70), new Color(230, 200, 40), new Color(240, 120, 30),
            new Color(200, 30, 30)};

    private ValidityReport() {
    }

    /** The CSV of the results, with a comment line saying what made it. */
    public static String csv(List<ValidityMap.Result> results, String command) {
        StringBuilder s = new StringBuilder("# the scalar model against Maxwell's equations (docs/measurements/validity.md), by `")
                .append(command).append("`\n").append(HEADER).append('\n');
        for (ValidityMap.Result r : results) {
            ValidityMap.Case c = r.c();
            s.append(String.format(Locale.ROOT, "%s,%s,%s,%s,%.4f,%.4f,%.4f,%.4f,%.4f,%d%n", c.family().label(),
                    Csv.number(c.periodUm()), Csv.number(c.depthUm()), Csv.number(c.thetaDeg()), r.deltaE(),
                    r.deltaEP95(), r.deltaEStam(), r.orderError(), r.orderErrorStam(), r.litPixels()));
        }
        return s.toString();
    }

    /** The results of a CSV {@link #csv} wrote (the cases a run already measured). */
    public static List<ValidityMap.Result> read(String csv) {
        List<ValidityMap.Result> out = new ArrayList<>();
        for (String line : csv.split("\n")) {
            if (line.isBlank() || line.startsWith("#") || line.startsWith("relief,")) {
                continue;
            }
            String[] f = line.split(",");
            ValidityMap.Case c = new ValidityMap.Case(ValidityMap.Family.parse(f[0]), Double.parseDouble(f[1]),
                    Double.parseDouble(f[2]), Double.parseDouble(f[3]));
            out.add(new ValidityMap.Result(c, Double.parseDouble(f[4]), Double.parseDouble(f[5]),
                    Double.parseDouble(f[6]), Double.parseDouble(f[7]), Double.parseDouble(f[8]),
                    Integer.parseInt(f[9].trim())));
        }
        return out;
    }

    /** The result of a case among {@code results}. */
    static Optional<ValidityMap.Result> find(List<ValidityMap.Result> results, ValidityMap.Case c) {
        return results.stream().filter(r -> r.c().equals(c)).findFirst();
    }

    /** One PNG per relief: a heat map of the default gain's CIEDE2000 per light angle, side by side. */
    public static List<Path> heatMaps(List<ValidityMap.Result> results, Path folder) throws IOException {
        Files.createDirectories(folder);
        List<Path> written = new ArrayList<>();
        for (ValidityMap.Family family : ValidityMap.Family.values()) {
            List<BufferedImage> panels = new ArrayList<>();
            for (double theta : ValidityMap.THETAS_DEG) {
                if (results.stream().anyMatch(r -> r.c().family() == family && r.c().thetaDeg() == theta)) {
                    panels.add(BitmapEncoder.getBufferedImage(heatMap(results, family, theta)));
                }
            }
            if (panels.isEmpty()) {
                continue;
            }
            int width = panels.stream().mapToInt(BufferedImage::getWidth).sum();
            int height = panels.stream().mapToInt(BufferedImage::getHeight).max().orElse(1);
            BufferedImage row = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
            Graphics2D g = row.createGraphics();
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, width, height);
            int x = 0;
            for (BufferedImage panel : panels) {
                g.drawImage(panel, x, 0, null);
                x += panel.getWidth();
            }
            g.dispose();
            Path png = folder.resolve("validity-" + family.label() + ".png");
            javax.imageio.ImageIO.write(row, "png", png.toFile());
            written.add(png);
        }
        return written;
    }

    private static HeatMapChart heatMap(List<ValidityMap.Result> results, ValidityMap.Family family, double theta) {
        HeatMapChart chart = new HeatMapChartBuilder().width(420).height(330)
                .title(String.format(Locale.ROOT, "%s, light at %.0f deg", family.label(), theta))
                .xAxisTitle("period (um)").yAxisTitle("peak-to-valley (um)").build();
        // one colour per unit of CIEDE2000 up to the top of the scale, each unit's its class's
        Color[] units = new Color[(int) TOP_OF_SCALE];
        for (int u = 0; u < units.length; u++) {
            units[u] = COLOURS[classOf(u + 0.5)];
        }
        chart.getStyler().setShowValue(true).setMin(0).setMax(TOP_OF_SCALE).setPiecewise(true)
                .setSplitNumber(units.length).setRangeColors(units).setHeatMapValueDecimalPattern("0.0")
                .setValueFont(new java.awt.Font(java.awt.Font.SANS_SERIF, java.awt.Font.PLAIN, 10));
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.getStyler().setLegendVisible(false);
        List<String> xs = ValidityMap.PERIODS_UM.stream().map(Csv::number).toList();
        List<String> ys = ValidityMap.DEPTHS_UM.stream().map(Csv::number).toList();
        List<Number[]> cells = new ArrayList<>();
        for (int i = 0; i < xs.size(); i++) {
            for (int j = 0; j < ys.size(); j++) {
                ValidityMap.Case c = new ValidityMap.Case(family, ValidityMap.PERIODS_UM.get(i),
                        ValidityMap.DEPTHS_UM.get(j), theta);
                Optional<ValidityMap.Result> r = find(results, c);
                if (r.isPresent()) {
                    // above the top of the scale a cell takes its colour and still shows its own value
                    cells.add(new Number[] {i, j, r.get().deltaE()});
                }
            }
        }
        chart.addSeries("CIEDE2000", xs, ys, cells);
        return chart;
    }

    /** The top of the heat maps' colour scale: CIEDE2000 above it is drawn in the top class's colour. */
    private static final double TOP_OF_SCALE = 12;

    private static int classOf(double deltaE) {
        for (int k = 0; k < BOUNDS.length; k++) {
            if (deltaE <= BOUNDS[k]) {
                return k;
            }
        }
        return BOUNDS.length - 1;
    }

    /**
     * The Markdown: what was measured, the heat maps, and per relief and light a table of CIEDE2000 (Rayleigh-Rice's
     * gain / Stam's) by period and depth, then the orders' largest relative errors.
     */
    public static String markdown(List<ValidityMap.Result> results, List<Path> images, Path docs, String command,
                                  double seconds) {
        StringBuilder s = new StringBuilder();
        s.append("# Where the scalar model holds: the validity map\n\n");
        s.append("Measured by `").append(command).append("` (").append(String.format(Locale.ROOT, "%.0f min", seconds
                / 60)).append(" on this machine; `bash docs/measurements/validity.sh` reruns it and copies its files here and into "
                + "`assets/validity/`). docs/design/rigorous.md says what the rigorous method is and how to read these numbers."
                + "\n\n");
        s.append("Each case is a 1-D relief of one shape, period and peak-to-valley height on keratin (n = 1.56), lit "
                + "by a point light in the plane of its period. The scalar model (Stam's, with its default gain, "
                + "Rayleigh-Rice's, and with Stam's own gain) and the rigorous method (Maxwell's equations) draw the row "
                + "of a " + ValidityMap.SIZE_PX + " x " + ValidityMap.SIZE_PX + " BRDF map through the orders, each pixel"
                + " its box's average, the wavelength integral exact; the colours are compared by CIEDE2000 over the "
                + "lit pixels, at the rigorous map's automatic exposure. The rigorous orders: wavelength nodes every "
                + Csv.number(ValidityMap.STEP_NM) + " nm, harmonics up to 2 period / lambda + 12, "
                + ValidityMap.LAYERS + " layers extrapolated from " + ValidityMap.LAYERS / 2 + ".\n\n");
        s.append("Colours of the maps: green CIEDE2000 <= 1 (side by side, no difference seen), yellow <= 3, orange "
                + "<= 10, red above; the number in a cell is its CIEDE2000 with Rayleigh-Rice's gain (the default).\n\n");
        for (Path image : images) {
            s.append("![").append(image.getFileName()).append("](").append(docs.relativize(image).toString()
                    .replace('\\', '/')).append(")\n\n");
        }
        for (ValidityMap.Family family : ValidityMap.Family.values()) {
            s.append("## ").append(family.label()).append("\n\n");
            for (double theta : ValidityMap.THETAS_DEG) {
                s.append(String.format(Locale.ROOT, "Light at %.0f degrees: mean CIEDE2000 over the lit pixels, "
                        + "Rayleigh-Rice's gain / Stam's.%n%n", theta));
                s.append("| depth \\ period (um) |");
                ValidityMap.PERIODS_UM.forEach(p -> s.append(' ').append(Csv.number(p)).append(" |"));
                s.append("\n|---|");
                ValidityMap.PERIODS_UM.forEach(p -> s.append("---|"));
                s.append('\n');
                for (double depth : ValidityMap.DEPTHS_UM) {
                    s.append("| ").append(Csv.number(depth)).append(" |");
                    for (double period : ValidityMap.PERIODS_UM) {
                        Optional<ValidityMap.Result> r = find(results, new ValidityMap.Case(family, period, depth,
                                theta));
                        s.append(r.map(x -> String.format(Locale.ROOT, " %.2g / %.2g |", x.deltaE(), x.deltaEStam()))
                                .orElse(" - |"));
                    }
                    s.append('\n');
                }
                s.append('\n');
            }
        }
        s.append("## The orders' efficiencies\n\n");
        s.append("The largest relative error of the scalar model on the orders that carry at least 5 % of the "
                + "reflected power, at 450, 550 and 650 nm (Rayleigh-Rice's gain / Stam's), for the cases the "
                + "rigorous method's design note lists:\n\n");
        s.append("| relief | period (um) | depth (um) | 0 deg | 30 deg | 60 deg |\n|---|---|---|---|---|---|\n");
        double[][] rows = {{0.65, 0.1}, {1.0, 0.1}, {1.144, 0.3}, {1.0, 0.3}, {1.5, 0.3}, {2.5, 0.1}};
        for (ValidityMap.Family family : ValidityMap.Family.values()) {
            for (double[] row : rows) {
                StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "| %s | %s | %s |", family.label(),
                        Csv.number(row[0]), Csv.number(row[1])));
                boolean any = false;
                for (double theta : ValidityMap.THETAS_DEG) {
                    Optional<ValidityMap.Result> r = find(results, new ValidityMap.Case(family, row[0], row[1],
                            theta));
                    any |= r.isPresent();
                    line.append(r.map(x -> String.format(Locale.ROOT, " %+.0f %% / %+.0f %% |", 100 * x.orderError(),
                            100 * x.orderErrorStam())).orElse(" - |"));
                }
                if (any) {
                    s.append(line).append('\n');
                }
            }
        }
        s.append('\n');
        return s.toString();
    }

    /** Writes {@code text} to {@code file} as UTF-8. */
    static void write(Path file, String text) throws IOException {
        Files.writeString(file, text, StandardCharsets.UTF_8);
    }
}
