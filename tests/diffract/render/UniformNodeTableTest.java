package diffract.render;

import diffract.util.TestReport;
import diffract.colour.Cie1931;
import diffract.colour.D65;
import diffract.colour.SpectralIntegrator;
import diffract.colour.Trapezoid;
import diffract.jrtr.textures.FloatTexture1D;
import diffract.optics.BrdfSettings;
import diffract.optics.Variant;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * The shader's wavelength loop runs only over the nodes where D65 x CMF is not zero. Inside the CIE
 * tables (380-780 nm) every node stays; a grid of 300-900 nm keeps exactly the nodes inside both tables.
 */
class UniformNodeTableTest {
    @Test
    void nodesWithoutWeightAreLeftOut() {
        BrdfSettings thesis = BrdfSettings.thesis(Variant.FLSS);
        assertEquals(81, DiffractionTextures.buildUniformNodeTable(thesis.spectral()).size(), "380-780 nm at 5 nm: all nodes");
        double first = Math.max(Cie1931.firstNm(), D65.firstNm());
        double last = Math.min(Cie1931.lastNm(), D65.lastNm());
        double[] nodes = Trapezoid.uniformNodes(300, 900, 10);
        double[][] weights = SpectralIntegrator.xyzWeights(nodes, Trapezoid.weights(nodes));
        int inside = 0;
        for (int j = 0; j < nodes.length; j++) {
            if (nodes[j] >= first && nodes[j] <= last && weights[j][0] + weights[j][1] + weights[j][2] > 0) {
                inside++;
            }
        }
        FloatTexture1D table = DiffractionTextures.buildUniformNodeTable(300, 900, 10, diffract.colour.MirrorNormalisation.PEAK);
        TestReport.printf(UniformNodeTableTest.class, "300-900 nm at 10 nm: %d of %d nodes carry weight (tables %.0f-%.0f nm)%n",
                table.size(), nodes.length, first, last);
        assertEquals(inside, table.size());
        assertEquals(true, table.size() < nodes.length);
    }
}
