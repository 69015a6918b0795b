package diffract.colour;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Tone mapping: stops double, Reinhard keeps chromaticity and maps its white to 1, nothing leaves [0, 1]. */
class ToneMappingTest {
    @Test
    void oneStopDoublesTheLight() {
        ToneMapping clip = new ToneMapping(ToneMapping.Operator.CLIP, 1, 1);
        assertEquals(0.5, clip.apply(new double[] {0.25, 0.1, 0})[0], 1e-15);
        assertEquals(0.25, new ToneMapping(ToneMapping.Operator.CLIP, -2, 1).apply(new double[] {1, 0, 0})[0], 1e-15);
    }

    @Test
    void reinhardMapsWhiteToOneAndKeepsHueAndSaturation() {
        ToneMapping reinhard = new ToneMapping(ToneMapping.Operator.REINHARD, 0, 4);
        double[] white = reinhard.apply(new double[] {4, 4, 4});
        assertEquals(1, white[0], 1e-12);
        assertEquals(1, white[2], 1e-12);
        // eq. 4 at Y = 1, Y_white = 4: (1 + 1/16) / 2
        assertEquals(17.0 / 32, reinhard.apply(new double[] {1, 1, 1})[1], 1e-12);
        double[] in = {0.9, 0.3, 0.05};
        double[] out = reinhard.apply(in);
        assertEquals(in[0] / in[1], out[0] / out[1], 1e-12);
        assertEquals(in[2] / in[1], out[2] / out[1], 1e-12);
        // a bright saturated colour stays saturated: scaled to its largest channel, not clipped per channel
        double[] bright = reinhard.apply(new double[] {40, 4, 0.4});
        assertEquals(1, bright[0], 1e-12);
        assertEquals(0.1, bright[1], 1e-12);
    }

    @Test
    void everyOperatorIsMonotonicAndStaysInTheUnitCube() {
        for (ToneMapping.Operator op : ToneMapping.Operator.values()) {
            ToneMapping t = new ToneMapping(op, 0.5, 3);
            double previous = -1;
            for (double x = 0; x < 1000; x = x * 1.3 + 0.001) {
                double[] out = t.apply(new double[] {x, x * 0.5, x * 0.1});
                for (double c : out) {
                    assertTrue(c >= 0 && c <= 1, op + " gives " + c);
                }
                assertTrue(out[1] >= previous - 1e-15, op + " not monotonic at " + x);
                previous = out[1];
            }
        }
    }
}
