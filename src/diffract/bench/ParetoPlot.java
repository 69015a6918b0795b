package diffract.bench;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The Pareto plot (XChart): mean CIEDE2000 (lit pixels) against GPU ms/frame, both axes logarithmic, one marker
 * series per patch (colour) and variant (marker shape), and each patch's Pareto front at the sweep's map size
 * ({@link ResultsTable#mainSize}) as a line of its colour. Zero errors are drawn at
 * {@link #ERROR_FLOOR}, which a log axis can show.
 */
public final class ParetoPlot {
    /** The smallest error drawn (CIEDE2000 0.001 is a thousandth of a just-noticeable difference). */
    public static final double ERROR_FLOOR = 1e-3;

    static final int WIDTH_PX = 1000;
    /** XChart centres the title over the plot area, the chart less the legend outside it on the right. */
    static final int TITLE_WIDTH_PX = 700;
    private static final float MIN_TITLE_POINTS = 8f;

    /** One colour per patch (points and front), one marker shape per variant. */
    private static final Color[] PATCH_COLOURS = {new Color(0, 90, 200), new Color(200, 60, 0), new Color(0, 150, 60),
            new Color(140, 0, 160), new Color(120, 120, 0), new Color(0, 140, 160)};
    private static final Marker[] VARIANT_MARKERS = {SeriesMarkers.CIRCLE, SeriesMarkers.DIAMOND, SeriesMarkers.SQUARE,
            SeriesMarkers.TRIANGLE_UP, SeriesMarkers.CROSS, SeriesMarkers.PLUS};

    private ParetoPlot() {
    }

    public static void write(Path png, List<BenchResult> results, String title) throws IOException {
        XYChart chart = new XYChartBuilder().width(WIDTH_PX).height(700).title(title)
                .xAxisTitle("GPU ms per frame (median, log)").yAxisTitle("mean CIEDE2000 vs CPU reference (lit pixels, log)")
                .build();
        chart.getStyler().setChartTitleFont(titleFont(chart.getStyler().getChartTitleFont(), title));
        chart.getStyler().setXAxisLogarithmic(true).setYAxisLogarithmic(true)
                .setLegendPosition(Styler.LegendPosition.OutsideE)
                .setChartBackgroundColor(Color.WHITE);
        List<String> patches = results.stream().map(r -> r.config().patch()).distinct().toList();
        List<String> variants = results.stream().map(r -> r.config().settings().variant().label()).distinct().toList();
        for (int p = 0; p < patches.size(); p++) {
            String patch = patches.get(p);
            Color colour = PATCH_COLOURS[p % PATCH_COLOURS.length];
            for (int v = 0; v < variants.size(); v++) {
                String variant = variants.get(v);
                List<BenchResult> points = results.stream().filter(r -> r.config().patch().equals(patch)
                        && r.config().settings().variant().label().equals(variant)
                        && !Double.isNaN(r.deltaEMean())).toList();
                if (!points.isEmpty()) {
                    XYSeries s = chart.addSeries(patch + " " + variant, xs(points), ys(points));
                    s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter)
                            .setMarker(VARIANT_MARKERS[v % VARIANT_MARKERS.length]).setMarkerColor(colour);
                }
            }
            List<BenchResult> front = ResultsTable.front(results, patch, ResultsTable.mainSize(results));
            if (front.size() > 1) {
                XYSeries line = chart.addSeries(patch + " Pareto front", xs(front), ys(front));
                line.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line).setMarker(SeriesMarkers.NONE)
                        .setLineColor(colour);
            }
        }
        Files.createDirectories(png.toAbsolutePath().getParent());
        String name = png.toString();
        BitmapEncoder.saveBitmap(chart, name.toLowerCase(Locale.ROOT).endsWith(".png")
                ? name.substring(0, name.length() - 4) : name, BitmapEncoder.BitmapFormat.PNG);
    }

    /**
     * XChart draws its title on one line, centred over the plot area, and cuts both ends of a title wider than that
     * (a long GL renderer's name does that): the font shrinks until the title fits, down to {@link #MIN_TITLE_POINTS}.
     */
    static Font titleFont(Font font, String title) {
        Graphics2D g = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics();
        try {
            Font fitted = font;
            while (fitted.getSize2D() > MIN_TITLE_POINTS
                    && g.getFontMetrics(fitted).stringWidth(title) > TITLE_WIDTH_PX) {
                fitted = fitted.deriveFont(fitted.getSize2D() - 0.5f);
            }
            return fitted;
        } finally {
            g.dispose();
        }
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
