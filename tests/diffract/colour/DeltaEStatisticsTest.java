package diffract.colour;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

class DeltaEStatisticsTest {

    @Test
    void identicalImagesDifferByZero() {
        float[] xyz = {0.2f, 0.3f, 0.1f, 0.9f, 1f, 1.1f};
        DeltaEStatistics s = DeltaEStatistics.of(xyz, xyz.clone(), null);
        assertEquals(2, s.pixels());
        assertEquals(0, s.max(), 0);
    }

    @Test
    void statisticsAreThoseOfThePerPixelCiede2000() {
        Xyz white = D65.whiteXyz();
        float[] a = new float[300];
        float[] b = new float[300];
        double sum = 0;
        double max = 0;
        for (int p = 0; p < 100; p++) {
            a[3 * p] = (float) (0.95 * p / 100);
            a[3 * p + 1] = (float) (1.0 * p / 100);
            a[3 * p + 2] = (float) (1.09 * p / 100);
            b[3 * p] = a[3 * p] * 1.02f;
            b[3 * p + 1] = a[3 * p + 1];
            b[3 * p + 2] = a[3 * p + 2] * 0.97f;
            double d = Ciede2000.deltaE(Lab.fromXyz(new Xyz(a[3 * p], a[3 * p + 1], a[3 * p + 2]), white),
                    Lab.fromXyz(new Xyz(b[3 * p], b[3 * p + 1], b[3 * p + 2]), white));
            sum += d;
            max = Math.max(max, d);
        }
        DeltaEStatistics s = DeltaEStatistics.of(a, b, null);
        assertEquals(sum / 100, s.mean(), 1e-12);
        assertEquals(max, s.max(), 1e-12);
        boolean[] firstHalf = new boolean[100];
        for (int p = 0; p < 50; p++) {
            firstHalf[p] = true;
        }
        assertEquals(50, DeltaEStatistics.of(a, b, firstHalf).pixels());
    }

    @Test
    void nearestRankPercentile() {
        double[] sorted = new double[100];
        for (int i = 0; i < 100; i++) {
            sorted[i] = i + 1;
        }
        assertEquals(95, DeltaEStatistics.percentile(sorted, 0.95), 0);
        assertEquals(99, DeltaEStatistics.percentile(sorted, 0.99), 0);
        assertThrows(IllegalArgumentException.class, () -> DeltaEStatistics.of(new float[3], new float[6], null));
    }
}
