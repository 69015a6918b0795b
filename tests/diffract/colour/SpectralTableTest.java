package diffract.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import org.junit.jupiter.api.Test;

class SpectralTableTest {
    private static SpectralTable parse(String csv, String column) throws IOException {
        return SpectralTable.fromCsv(new StringReader(csv), column, "test.csv");
    }

    @Test
    void readsTheNamedColumnSkippingComments() throws IOException {
        SpectralTable t = parse("# a comment\n# another\nlambda_nm,a,b\n400,1,10\n410,3,20\n420,5,40\n", "b");
        assertEquals(400.0, t.firstNm());
        assertEquals(420.0, t.lastNm());
        assertEquals(10.0, t.stepNm());
        assertEquals(3, t.nodeCount());
        assertEquals(20.0, t.at(410), 0);
        assertEquals(15.0, t.at(405), 1e-15);
        assertEquals(38.0, t.at(419), 1e-12);
        assertEquals(40.0, t.at(420), 0);
        assertEquals(0.0, t.at(399.99));
        assertEquals(0.0, t.at(420.01));
        assertTrue(Double.isNaN(t.at(Double.NaN)));
    }

    @Test
    void rejectsMalformedTables() {
        assertThrows(IllegalArgumentException.class, () -> parse("lambda_nm,a\n400,1\n", "a"));
        assertThrows(IllegalArgumentException.class, () -> parse("lambda_nm,a\n400,1\n410,2\n", "missing"));
        assertThrows(IllegalArgumentException.class, () -> parse("lambda_nm,a\n400,1\n410,x\n", "a"));
        assertThrows(IllegalArgumentException.class, () -> parse("lambda_nm,a\n400,1\n410,2\n425,3\n", "a"));
        assertThrows(IllegalArgumentException.class, () -> parse("lambda_nm,a\n400,1\n390,2\n", "a"));
        assertThrows(IllegalArgumentException.class, () -> parse("lambda_nm,a\n400,1\n410,NaN\n", "a"));
        assertThrows(IllegalArgumentException.class, () -> parse("lambda_nm,a,b\n400,1\n410,2\n", "b"));
    }

    @Test
    void missingResourceIsReported() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SpectralTable.fromCsvResource("/assets/colour/no_such_table.csv", "a"));
        assertTrue(e.getMessage().contains("no_such_table.csv"), e.getMessage());
    }

    @Test
    void uniformFactoryCopiesAndValidates() {
        double[] values = {0, 2};
        SpectralTable t = SpectralTable.uniform(500, 2, values);
        values[1] = 100;
        assertEquals(1.0, t.at(501), 0);
        assertThrows(IllegalArgumentException.class, () -> SpectralTable.uniform(500, 0, new double[] {1, 2}));
        assertThrows(IllegalArgumentException.class, () -> SpectralTable.uniform(500, 1, new double[] {1}));
    }
}
