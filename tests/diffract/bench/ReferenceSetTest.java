package diffract.bench;

import diffract.optics.maps.AutoExposure;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.LobeQuadrature;
import diffract.optics.Variant;
import diffract.util.DiskCache;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The reference maps a variant is measured against: each light's map as the reference computes it, with its own
 * exposure; the variant drawn for the brightest of them; the error of the references themselves zero.
 */
class ReferenceSetTest {
    private static final List<Double> LIGHTS_DEG = List.of(0.0, 45.0);

    @Test
    void eachLightHasItsReferenceMapAndItsOwnExposure(@TempDir Path root) {
        ReferenceMaps maps = new ReferenceMaps(DiskCache.at(root), Reporter.SILENT);
        ReferenceSet set = ReferenceSet.of(maps, ReferenceMapsTest.GRATING, LIGHTS_DEG, ReferenceMapsTest.SIZE,
                ReferenceMapsTest.BASE);
        assertEquals(2, set.xyz().size());
        for (int i = 0; i < LIGHTS_DEG.size(); i++) {
            Direction wi = Direction.fromSphericalDeg(LIGHTS_DEG.get(i), ReferenceMapsTest.GRATING.phiIDeg());
            assertEquals(wi, set.lights().get(i));
            float[] expected = maps.xyz(ReferenceMapsTest.GRATING, LIGHTS_DEG.get(i), ReferenceMapsTest.SIZE,
                    ReferenceMapsTest.BASE);
            assertArrayEquals(expected, set.xyz().get(i));
            assertEquals(AutoExposure.ofXyz(expected, wi, ReferenceMapsTest.SIZE), set.exposures().get(i));
        }
        assertNotEquals(set.exposures().get(0), set.exposures().get(1), "the lights' maps differ in brightness");

        MapError itself = set.error(set.xyz());
        assertTrue(itself.litPixels() > 0, "some pixels are lit");
        assertEquals(0, itself.mean());
        assertEquals(0, itself.diskMean());
        // a map twice as bright is measured at the reference's exposure, not its own: visibly off
        List<float[]> brighter = set.xyz().stream().map(ReferenceSetTest::doubled).toList();
        assertTrue(set.error(brighter).mean() > 1, "twice as bright: " + set.error(brighter).mean());
    }

    @Test
    void aVariantIsDrawnForTheBrightestExposureItIsComparedAt() {
        BrdfSettings lobes = BrdfSettings.thesis(Variant.LOBES);
        double cutoff = lobes.lobes().cutoff();
        assertTrue(cutoff > 0);
        float[] map = new float[3];
        List<Direction> lights = List.of(Direction.fromSphericalDeg(0, 0), Direction.fromSphericalDeg(45, 0));
        double e = LobeQuadrature.CUTOFF_EXPOSURE;
        ReferenceSet set = new ReferenceSet(lights, 1, List.of(map, map), List.of(10 * e, 100 * e));
        assertEquals(cutoff / 100, set.drawnFor(lobes).lobes().cutoff(), cutoff * 1e-12);
        ReferenceSet dim = new ReferenceSet(set.lights(), 1, set.xyz(), List.of(1.0, e));
        assertEquals(cutoff, dim.drawnFor(lobes).lobes().cutoff(), "shown no brighter than the cutoff assumes");
    }

    private static float[] doubled(float[] xyz) {
        float[] d = xyz.clone();
        for (int i = 0; i < d.length; i++) {
            d[i] *= 2;
        }
        return d;
    }
}
