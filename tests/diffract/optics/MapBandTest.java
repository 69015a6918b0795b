package diffract.optics;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** N bands of a map's rows cover every row once, in order, and differ in height by at most one row. */
class MapBandTest {
    @Test
    void bandsCoverEveryRowOnceAndEvenly() {
        for (int size : new int[] {1, 7, 24, 96, 8192}) {
            for (int count = 1; count <= Math.min(size, 40); count++) {
                int next = 0;
                int fewest = Integer.MAX_VALUE;
                int most = 0;
                for (int i = 0; i < count; i++) {
                    MapBand band = MapBand.of(i, count, size);
                    assertEquals(next, band.fromRow(), size + " rows, band " + i + "/" + count);
                    next = band.toRow();
                    fewest = Math.min(fewest, band.rows());
                    most = Math.max(most, band.rows());
                }
                assertEquals(size, next);
                assertTrue(most - fewest <= 1, size + " rows in " + count + " bands");
            }
        }
    }

    @Test
    void theThreeBandsOf24RowsAreEightRowsEach() {
        assertEquals(new MapBand(0, 8), MapBand.of(0, 3, 24));
        assertEquals(new MapBand(8, 16), MapBand.of(1, 3, 24));
        assertEquals(new MapBand(16, 24), MapBand.of(2, 3, 24));
        assertEquals("8..15", MapBand.of(1, 3, 24).toString());
    }

    @Test
    void moreBandsThanRowsOrAnIndexOutsideAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> MapBand.of(0, 25, 24));
        assertThrows(IllegalArgumentException.class, () -> MapBand.of(3, 3, 24));
        assertThrows(IllegalArgumentException.class, () -> MapBand.of(-1, 3, 24));
    }
}
