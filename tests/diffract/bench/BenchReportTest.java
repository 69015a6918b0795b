package diffract.bench;

import diffract.optics.BrdfSettings;
import diffract.optics.Variant;
import org.junit.jupiter.api.Test;

import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** What the bench writes for people to read: the targets table and the Pareto plot's title. */
class BenchReportTest {
    @Test
    void aPatchThatNoConfigurationServesHasNoSpeedUpRatherThanNaN() {
        BenchResult thesis = new BenchResult(new BenchConfig("tall", BrdfSettings.thesis(Variant.FLSS), 64), 230,
                new MapError(29.6, 40, 1, 700));
        String table = Targets.markdown(java.util.List.of(
                new Targets.Outcome("tall", thesis, Optional.empty(), Optional.empty(), null, null, null)));
        assertFalse(table.contains("NaN"), table);
        assertTrue(table.contains("| tall | 230.00 (29.600) | none meets it | - | - | **no** | none |"), table);
    }

    @Test
    void theFastestConfigurationWithinOneIsChosenApartFromAutosAndItsSpeedUpIsOnTheThesisFlss() {
        BenchResult thesis = new BenchResult(new BenchConfig("tall", BrdfSettings.thesis(Variant.FLSS), 64), 200,
                new MapError(21.4, 40, 1, 700));
        BenchResult fastLoose = new BenchResult(new BenchConfig("tall", BrdfSettings.thesis(Variant.LOBES)
                .with(b -> b.highestOrder(4)), 64), 4, new MapError(1.6, 3, 1, 700));
        BenchResult slowerClose = new BenchResult(new BenchConfig("tall", BrdfSettings.thesis(Variant.LOBES)
                .with(b -> b.highestOrder(8)), 64), 8, new MapError(0.4, 1, 1, 700));
        Targets.Outcome o = Targets.of(java.util.List.of(thesis, fastLoose, slowerClose), 64, c -> null,
                (patch, size) -> java.util.List.of()).get(0);
        assertEquals(4, o.autoChoice().orElseThrow().chosen().msPerFrame());
        assertEquals(8, o.closeChoice().orElseThrow().chosen().msPerFrame());
        assertEquals(25, o.closeSpeedUp(), 1e-12);
        String table = Targets.markdown(java.util.List.of(o));
        assertTrue(table.contains("| lobes, N = 8: 8.00 (0.400), 25.0x |"), table);
    }

    @Test
    void aTitleWiderThanThePlotShrinksUntilItFitsAndAShortOneKeepsItsSize() {
        Font base = new Font(Font.SANS_SERIF, Font.BOLD, 16);
        String shortTitle = "diffract bench";
        assertEquals(base.getSize2D(), ParetoPlot.titleFont(base, shortTitle).getSize2D());
        String longTitle = "diffract bench: error against GPU time per frame (64x64, llvmpipe (LLVM 15.0.6, 256 bits), "
                + "OpenGL 4.5 (Core Profile) Mesa 22.3.6)";
        Font fitted = ParetoPlot.titleFont(base, longTitle);
        Graphics2D g = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics();
        assertTrue(g.getFontMetrics(base).stringWidth(longTitle) > ParetoPlot.WIDTH_PX, "the case is a real one");
        assertTrue(fitted.getSize2D() < base.getSize2D());
        assertTrue(g.getFontMetrics(fitted).stringWidth(longTitle) <= ParetoPlot.TITLE_WIDTH_PX,
                "width " + g.getFontMetrics(fitted).stringWidth(longTitle));
        g.dispose();
    }
}
