package diffract.bench;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The Pareto plot (XChart): mean CIEDE2000 (lit pixels) against GPU ms/frame, both axes logarithmic, one marker
 * series per patch and variant, and each patch's Pareto front as a line. Zero errors are drawn at
 * {@link #ERROR_FLOOR}, which a log axis can show.
 */
public final class ParetoPlot {
    /** The smallest error drawn (CIEDE2000 0.001 is a thousandth of a just-noticeable difference). */
    public static final double ERROR_FLOOR = 1e-3;

    private ParetoPlot() {
    }

    public static void write(Path png, List<BenchResult> results, String title) throws IOException {
        XYChart chart = new XYChartBuilder().width(1000).height(700).title(title)
                .xAxisTitle("GPU ms per frame (median, log)").yAxisTitle("mean CIEDE2000 vs CPU reference (lit pixels, log)")
                .build();
        chart.getStyler().setXAxisLogarithmic(true).setYAxisLogarithmic(true)
                .setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideE)
                .setChartBackgroundColor(java.awt.Color.WHITE);
        List<String> patches = results.stream().map(r -> r.config().patch()).distinct().toList();
        List<String> variants = results.stream().map(r -> r.config().settings().variant().cliName()).distinct().toList();
        for (String patch : patches) {
            for (String variant : variants) {
                List<BenchResult> points = results.stream().filter(r -> r.config().patch().equals(patch)
                        && r.config().settings().variant().cliName().equals(variant)
                        && !Double.isNaN(r.deltaEMean())).toList();
                if (!points.isEmpty()) {
                    XYSeries s = chart.addSeries(patch + " " + variant, xs(points), ys(points));
                    s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
                }
            }
            List<BenchResult> front = ResultsTable.front(results, patch);
            if (front.size() > 1) {
                XYSeries line = chart.addSeries(patch + " Pareto front", xs(front), ys(front));
                line.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line).setMarker(SeriesMarkers.NONE);
            }
        }
        Files.createDirectories(png.toAbsolutePath().getParent());
        String name = png.toString();
        BitmapEncoder.saveBitmap(chart, name.toLowerCase(Locale.ROOT).endsWith(".png")
                ? name.substring(0, name.length() - 4) : name, BitmapEncoder.BitmapFormat.PNG);
    }

    private static List<Double> xs(List<BenchResult> points) {
        List<Double> x = new ArrayList<>();
        points.forEach(r -> x.add(r.msPerFrame()));
        return x;
    }

    private static List<Double> ys(List<BenchResult> points) {
        List<Double> y = new ArrayList<>();
        points.forEach(r -> y.add(Math.max(ERROR_FLOOR, r.deltaEMean())));
        return y;
    }
}
