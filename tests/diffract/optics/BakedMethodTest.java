package diffract.optics;

import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.Quantity;
import diffract.optics.windows.WindowPlacement;
import org.junit.jupiter.api.Test;

import java.util.Optional;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The baked method takes the method its table holds: {@code baked(of=lobes)} and {@code baked(of=flss)} name it,
 * plain {@code baked} chooses it per scene (the lobes method where the illumination filters and the lobes shader takes
 * the patch, FLSS otherwise); what it answers follows the method it holds.
 */
class BakedMethodTest {
    private static final BrdfSettings POINT = BrdfSettings.thesis(Variant.BAKED).with(b -> b.lightSizeDeg(0)
            .pixelFilter(PixelFilter.POINT));
    private static final BrdfSettings FILTERED = POINT.with(b -> b.pixelFilter(PixelFilter.BOX).lightSizeDeg(2));

    @Test
    void itParsesWithItsParameterInAnyCaseAndSpacing() {
        Variant lobes = Variant.parse("baked(of=lobes)");
        assertEquals(lobes, Variant.parse(" Baked ( of = LOBES ) "));
        assertEquals(Variant.BAKED.of(Variant.LOBES), lobes);
        assertEquals("baked(of=lobes)", lobes.spec());
        assertEquals("baked", lobes.label(), "one shader, one registry entry: baked.frag");
        assertEquals(Variant.parse("baked(of=flss)").hashCode(), Variant.BAKED.of(Variant.FLSS).hashCode());
        assertNotEquals(Variant.parse("baked(of=flss)"), lobes);
        assertNotEquals(Variant.BAKED, lobes);
        assertEquals(lobes, Variant.parse(lobes.spec()), "its spec parses back");
    }

    @Test
    void onlyMethodsWithABakePassCanBeHeldAndOnlyBakedHoldsOne() {
        for (Variant v : Variant.values()) {
            if (v.bakeable()) {
                assertEquals(Optional.of(v), Variant.BAKED.of(v).tabulated(POINT, 10, 10), v.label());
            } else {
                InvalidSettingException e = assertThrows(InvalidSettingException.class, () -> Variant.BAKED.of(v));
                assertTrue(e.getMessage().startsWith("a baked table holds flss or lobes, not " + v.spec()),
                        e.getMessage());
            }
            if (!v.drawsTable()) {
                InvalidSettingException e = assertThrows(InvalidSettingException.class, () -> v.of(Variant.FLSS));
                assertEquals(v.label() + " takes no other method; " + v.label() + "(of=flss) is not a method",
                        e.getMessage());
                assertEquals(Optional.empty(), v.tabulated(POINT, 10, 10), v.label());
            }
        }
        assertEquals(Quantity.VARIANT, assertThrows(InvalidSettingException.class,
                () -> Variant.parse("baked(of=baked(of=lobes))")).quantity());
    }

    @Test
    void plainBakedChoosesByTheIlluminationAndThePatch() {
        assertEquals(Optional.of(Variant.FLSS), Variant.BAKED.tabulated(POINT, 10, 10), "a point light, point pixels");
        assertEquals(Optional.of(Variant.LOBES), Variant.BAKED.tabulated(FILTERED, 10, 10), "a light and boxes");
        // a window fixed at the DFT's origin on a patch this wide keeps texel pairs, which the lobes shader does not sum
        BrdfSettings fixed = FILTERED.with(b -> b.windowPlacement(WindowPlacement.FIXED));
        assertTrue(Variant.LOBES.patchRefusal(fixed, 200, 200).isPresent());
        assertEquals(Optional.empty(), Variant.LOBES.patchRefusal(FILTERED, 200, 200), "the averaged window keeps none");
        assertEquals(Optional.of(Variant.FLSS), Variant.BAKED.tabulated(fixed, 200, 200));
        assertEquals(Variant.LOBES.patchRefusal(fixed, 200, 200),
                Variant.BAKED.of(Variant.LOBES).patchRefusal(fixed, 200, 200),
                "a table of the lobes method refuses what the lobes method refuses");
        assertEquals(Optional.empty(), Variant.BAKED.patchRefusal(fixed, 200, 200), "plain baked falls back instead");
    }

    @Test
    void itFiltersTheLightWhereTheMethodItHoldsDoes() {
        assertTrue(Variant.BAKED.filtersLight());
        assertTrue(Variant.BAKED.of(Variant.LOBES).filtersLight());
        assertFalse(Variant.BAKED.of(Variant.FLSS).filtersLight());
        assertTrue(LightPolicy.of(FILTERED.with(b -> b.variant(Variant.BAKED.of(Variant.FLSS)))).notice().isPresent(),
                "a table of FLSS samples the light at its centre, as FLSS does");
    }

    /** The heap it needs: the method it bakes and its float32 table, 12 bytes a sample. */
    @Test
    void itsMemoryIsItsMethodsAndItsTable() {
        HeightField field = SyntheticPatches.blazed(2.5, 0.3, 16, 4, 16).meanSubtracted();
        BrdfSettings s = FILTERED.with(b -> b.bakedSamples(33, 5));
        long flss = Variant.FLSS.heapMemory(field, s, 30, 380, 780).bytes();
        long table = Variant.BAKED.of(Variant.FLSS).heapMemory(field, s, 30, 380, 780).bytes() - flss;
        assertEquals(33L * 33 * 5 * 12, table);
        assertTrue(Variant.BAKED.heapMemory(field, s, 30, 380, 780).bytes()
                > Variant.LOBES.heapMemory(field, s, 30, 380, 780).bytes(), "plain baked counts the lobes method");
    }
}
