package diffract.render;

import diffract.util.Reporter;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The reader of frames whose lobes loops the GL ended early: alpha 0 marks a pixel left short. */
class ShortPixelsTest {
    @Test
    void itKeepsTheColoursAndCountsThePixelsOfAlphaZeroOverFrames() {
        ShortPixels shortPixels = new ShortPixels();
        float[] first = shortPixels.rgbOf(new float[] {0.1f, 0.2f, 0.3f, 1, 0.4f, 0.5f, 0.6f, 0, 0.7f, 0.8f, 0.9f, 1});
        assertArrayEquals(new float[] {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f, 0.9f}, first);
        assertEquals(1, shortPixels.count());
        shortPixels.rgbOf(new float[] {0, 0, 0, 0, 1, 1, 1, 0.5f});
        assertEquals(2, shortPixels.count(), "a second frame adds its own; alpha 0.5 is not short");

        Reporter.Collecting reporter = new Reporter.Collecting();
        shortPixels.warnIfAny(reporter, "pixels of the frames", "llvmpipe", "draw it on a GPU");
        assertEquals(List.of("2 of the 5 pixels of the frames reach more lobes than llvmpipe lets one fragment sum "
                + "(its loops were ended early; Mesa's llvmpipe ends them after 65535 iterations): they miss lobes and "
                + "are too dark; draw it on a GPU"), reporter.warnings());
    }

    @Test
    void aWholeFrameSaysNothing() {
        ShortPixels shortPixels = new ShortPixels();
        shortPixels.rgbOf(new float[] {0.5f, 0.5f, 0.5f, 1, 0, 0, 0, 1});
        Reporter.Collecting reporter = new Reporter.Collecting();
        shortPixels.warnIfAny(reporter, "pixels of the frame", "llvmpipe", "draw it on a GPU");
        assertTrue(reporter.warnings().isEmpty(), reporter.warnings().toString());
        assertEquals(0, shortPixels.count());
    }
}
