package diffract.render;

import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Assumptions;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/** Patches, settings and the display assumption shared by the GPU tests. */
final class RenderTestSupport {
    /**
     * A blazed grating of period 2.5 um, 0.13 um high (no blaze extinction in 380-780 nm, as GratingEquationTest),
     * 4 periods of 20 pixels across, 16 rows: 80 x 16 pixels of 0.125 um, a 10 x 2 um patch.
     */
    static final HeightField BLAZED = SyntheticPatches.blazed(2.5, 0.13, 20, 4, 16).meanSubtracted();
    /** The procedural Elaphe-like patch: 128 x 128 pixels of 0.0715 um, ridges along x, period 1.144 um along y. */
    static final HeightField ELAPHE_LIKE = SyntheticPatches.elapheLike().meanSubtracted();

    /** A scan as wide as three quarters of the 65 um coherence length: 128 x 128 pixels of 0.375 um, ridges along x. */
    static final HeightField WIDE = diffract.optics.WideScan.of(128, 0.375);

    private static final Map<HeightField, TaylorTerms> TERMS = new ConcurrentHashMap<>();

    private RenderTestSupport() {
    }

    /** GL tests are skipped, not failed, where no X display exists. */

    /** Terms 0..30 of a patch, computed once per test run. */
    static TaylorTerms terms(HeightField patch) {
        return TERMS.computeIfAbsent(patch, p -> TaylorTermComputer.compute(p, 30, Reporter.SILENT));
    }

    /**
     * The thesis' configuration (30 terms, 3 x 3 window, 5 nm over 380-780 nm, n = 1.5) except two choices that
     * make the pictures worth comparing on small maps: a coherence length 4 sigma_s of 10 um instead of 65 um
     * (the orders of a 10 um patch are then a few map pixels wide instead of far below one, so many pixels are
     * lit), and 3 PQ replicas per axis (the automatic count, round(10 um / extent), would be 1 for the
     * 10 um patches and switch the replication factor off).
     */
    static BrdfSettings settings(Variant variant) {
        return BrdfSettings.builder(variant).highestOrder(30).windowRadius(1).lambdaRangeNm(380, 780).lambdaStepNm(5).coherenceLengthUm(4 * 2.5).refractiveIndex(1.5).pqReplicas(3).build();
    }

    /** Light in the plane of the period: along x for the grating, along y for the Elaphe-like ridges. */
    static Direction light(HeightField patch, double thetaIDeg) {
        return Direction.fromSphericalDeg(thetaIDeg, patch == ELAPHE_LIKE || patch == WIDE ? 90 : 0);
    }

    /**
     * Both maps through the exposure {@link diffract.optics.maps.AutoExposure} picks for the first (the CPU's): its
     * brightest diffracted pixel maps to Y = 1, so the orders, not the specular peak, fill the display range.
     */
    static diffract.optics.maps.BrdfMapDifference difference(float[] cpuXyz, float[] gpuXyz, int size, Direction wi) {
        double exposure = diffract.optics.maps.AutoExposure.ofXyz(cpuXyz, wi, size);
        return diffract.optics.maps.BrdfMapDifference.of(cpuXyz, gpuXyz, size, exposure);
    }

    /** The XYZ of a size x size BRDF map drawn by the GPU under {@code settings}, in a GL context of its own. */
    static float[] gpuXyz(TaylorTerms terms, BrdfSettings settings, Direction wi, int size) {
        try (GpuBrdfMap map = new GpuBrdfMap(terms, settings)) {
            return map.xyz(wi, size);
        }
    }

    static String name(HeightField patch) {
        return patch == ELAPHE_LIKE ? "elaphe-like" : patch == WIDE ? "48 um scan" : "blazed";
    }
}
