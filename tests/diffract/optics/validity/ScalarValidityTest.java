package diffract.optics.validity;

import diffract.optics.patches.PatchCatalogue;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.settings.GainModel;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The validity table the warnings read: a patch summed up by its period and depth, the table interpolated between its
 * cases and the worst relief shape taken, and the shipped table on both sides of the boundary.
 */
class ScalarValidityTest {
    /** Two reliefs, two periods, two depths, two angles; Stam's column is twice Rayleigh-Rice's. */
    static final String TABLE = """
            # a test table
            relief,periodUm,depthUm,thetaDeg,deltaE,deltaEP95,deltaEStam,orderError,orderErrorStam,litPixels
            sinusoid,1,0.1,0,1,0,2,0,0,10
            sinusoid,1,0.1,30,2,0,4,0,0,10
            sinusoid,1,0.2,0,3,0,6,0,0,10
            sinusoid,1,0.2,30,4,0,8,0,0,10
            sinusoid,4,0.1,0,0.5,0,1,0,0,10
            sinusoid,4,0.1,30,0.5,0,1,0,0,10
            sinusoid,4,0.2,0,1.5,0,3,0,0,10
            sinusoid,4,0.2,30,1.5,0,3,0,0,10
            sawtooth,1,0.1,0,5,0,5,0,0,10
            """;

    @Test
    void theTableIsExactAtItsCasesAndLinearBetween() {
        ScalarValidity v = ScalarValidity.parse(TABLE);
        assertEquals(2, v.estimate(1, 0.1, 30, GainModel.RAYLEIGH_RICE).deltaE(), 1e-12);
        assertEquals(8, v.estimate(1, 0.2, 30, GainModel.STAM).deltaE(), 1e-12);
        assertEquals(3, v.estimate(1, 0.15, 30, GainModel.RAYLEIGH_RICE).deltaE(), 1e-12, "linear in depth");
        assertEquals(1.5, v.estimate(1, 0.1, 15, GainModel.RAYLEIGH_RICE).deltaE(), 1e-12, "linear in angle");
        assertEquals(0.75, v.estimate(2, 0.1, 0, GainModel.RAYLEIGH_RICE).deltaE(), 1e-12,
                "linear in log period: 2 um is half way from 1 to 4");
        assertEquals(1, v.estimate(1, 0.05, 30, GainModel.RAYLEIGH_RICE).deltaE(), 1e-12, "towards 0 at depth 0");
        assertEquals(0, v.estimate(4, 0, 0, GainModel.RAYLEIGH_RICE).deltaE(), 1e-12, "a mirror is exact");
    }

    /** The worst shape counts where it was measured; a case it lacks leaves the other shape's value. */
    @Test
    void theWorstReliefShapeCounts() {
        ScalarValidity v = ScalarValidity.parse(TABLE);
        assertEquals(5, v.estimate(1, 0.1, 0, GainModel.RAYLEIGH_RICE).deltaE(), 1e-12);
        assertEquals(1.5, v.estimate(4, 0.2, 30, GainModel.RAYLEIGH_RICE).deltaE(), 1e-12);
    }

    @Test
    void beyondTheTableItClampsAndSaysAtLeast() {
        ScalarValidity v = ScalarValidity.parse(TABLE);
        ScalarValidity.Estimate deep = v.estimate(1, 0.5, 30, GainModel.RAYLEIGH_RICE);
        assertTrue(deep.outsideTable());
        assertEquals(4, deep.deltaE(), 1e-12);
        assertTrue(deep.describe().contains("at least CIEDE2000 4.0"), deep.describe());
        assertFalse(v.estimate(1, 0.15, 15, GainModel.RAYLEIGH_RICE).outsideTable());
        assertThrows(IllegalArgumentException.class, () -> ScalarValidity.parse("sinusoid,1,0.1,0,1,0,2,0,0,10\n"));
    }

    /** A 1-D grating is its own period and peak-to-valley; a 2-D patch its strongest period and 2 sqrt 2 rms. */
    @Test
    void aPatchIsSummedUpByItsPeriodAndDepth() {
        double[] grating = ScalarValidity.periodAndDepth(SyntheticPatches.sinusoid(1.5, 0.2, 25, 6, 16)
                .meanSubtracted());
        assertEquals(1.5, grating[0], 1e-9);
        assertEquals(0.2, grating[1], 1e-3);
        double[] snake = ScalarValidity.periodAndDepth(PatchCatalogue.named("elaphe-like").build().meanSubtracted());
        assertEquals(SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, snake[0], 0.01, "the ridges' period");
        assertTrue(snake[1] > 0.1 && snake[1] < 0.35, "depth " + snake[1]);
    }

    /**
     * The shipped table on both sides of the boundary: the Elaphe-like ridge (1.144 um, 0.3 um deep) is visibly off at
     * 30 degrees, a shallow 2.5 um sinusoid near the normal is not.
     */
    @Test
    void theShippedTableWarnsOnTheRidgesAndNotOnShallowGratings() {
        ScalarValidity shipped = ScalarValidity.shipped();
        ScalarValidity.Estimate ridge = shipped.estimate(PatchCatalogue.named("elaphe-ridge").build().meanSubtracted(),
                30, GainModel.RAYLEIGH_RICE);
        assertTrue(ridge.visible() && ridge.deltaE() > 3, ridge.describe());
        ScalarValidity.Estimate shallow = shipped.estimate(SyntheticPatches.sinusoid(2.5, 0.025, 25, 6, 16)
                .meanSubtracted(), 0, GainModel.RAYLEIGH_RICE);
        assertFalse(shallow.visible(), shallow.describe());
    }
}
