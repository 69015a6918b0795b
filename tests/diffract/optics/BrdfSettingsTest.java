package diffract.optics;

import diffract.optics.illumination.GainFactor;
import diffract.optics.illumination.IlluminationSettings;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.OrderWeights;
import diffract.optics.settings.Quantity;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.settings.TermFormat;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.spectra.TaylorSettings;
import diffract.optics.spectra.WindowSettings;
import diffract.optics.windows.WindowPlacement;
import org.junit.jupiter.api.Test;

import java.lang.reflect.RecordComponent;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import java.util.function.Supplier;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The settings' builder changes the group of the value it sets and carries every other group; each group refuses
 * a value outside its one range, naming the quantity.
 */
class BrdfSettingsTest {
    private static final BrdfSettings START = BrdfSettings.builder(Variant.NMM).highestOrder(12).windowRadius(2)
            .lambdaRangeNm(400, 700).lambdaStepNm(10).coherenceLengthUm(12).refractiveIndex(1.4).pqReplicas(2)
            .taylorTolerance(1e-5).automaticWindowRadius(true).bakedSamples(64, 9).expansion(TaylorExpansion.CENTRED)
            .termFormat(TermFormat.RG16F).build();

    @Test
    void eachBuilderValueChangesOnlyItsGroup() throws Exception {
        Map<String, Consumer<BrdfSettings.Builder>> edits = Map.ofEntries(
                Map.entry("variant", b -> b.variant(Variant.PQ)),
                Map.entry("taylor highestOrder", b -> b.highestOrder(20)),
                Map.entry("taylor tolerance", b -> b.taylorTolerance(0)),
                Map.entry("taylor expansion", b -> b.expansion(TaylorExpansion.PLAIN)),
                Map.entry("window radius automatic", b -> b.windowRadius(3)),
                Map.entry("window automatic", b -> b.automaticWindowRadius(false)),
                Map.entry("window pqReplicas", b -> b.pqReplicas(0)),
                Map.entry("spectral lambdaStepNm", b -> b.lambdaStepNm(1)),
                Map.entry("spectral lambdaMinNm lambdaMaxNm", b -> b.lambdaRangeNm(380, 780)),
                Map.entry("illumination sigmaSpatialUm", b -> b.coherenceLengthUm(65)),
                Map.entry("illumination refractiveIndex", b -> b.refractiveIndex(1.5)),
                Map.entry("gpu termFormat", b -> b.termFormat(TermFormat.RG8)),
                Map.entry("gpu bakedUvSamples bakedWSamples", b -> b.bakedSamples(128, 13)));
        for (var edit : edits.entrySet()) {
            BrdfSettings changed = START.with(edit.getValue());
            List<String> differing = new ArrayList<>();
            for (RecordComponent group : BrdfSettings.class.getRecordComponents()) {
                Object before = group.getAccessor().invoke(START);
                Object after = group.getAccessor().invoke(changed);
                if (!before.getClass().isRecord()) {
                    if (!before.equals(after)) {
                        differing.add(group.getName());
                    }
                    continue;
                }
                for (RecordComponent c : before.getClass().getRecordComponents()) {
                    if (!c.getAccessor().invoke(before).equals(c.getAccessor().invoke(after))) {
                        if (!differing.contains(group.getName())) {
                            differing.add(group.getName());
                        }
                        differing.add(c.getName());
                    }
                }
            }
            assertEquals(List.of(edit.getKey().split(" ")), differing, edit.getKey());
        }
    }

    @Test
    void theThesisConfigurationIsTheDefault() {
        BrdfSettings thesis = BrdfSettings.thesis(Variant.FLSS);
        assertEquals(30, thesis.taylor().highestOrder());
        assertEquals(0, thesis.taylor().tolerance());
        assertEquals(TaylorExpansion.AUTO, thesis.taylor().expansion());
        assertEquals(new WindowSettings(1, false, 0, WindowPlacement.AVERAGED), thesis.window());
        assertEquals(new SpectralSettings(380, 780, 5), thesis.spectral());
        assertEquals(65, thesis.illumination().coherenceLengthUm(), 1e-12);
        assertEquals(GainFactor.KERATIN_REFRACTIVE_INDEX, thesis.illumination().refractiveIndex());
        assertEquals(GainModel.RAYLEIGH_RICE, thesis.illumination().gain());
        assertEquals(TermFormat.RG32F, thesis.gpu().termFormat());
        assertEquals(thesis, BrdfSettings.builder(Variant.FLSS).build());
    }

    @Test
    void eachGroupRefusesValuesOutsideItsRangeAndNamesTheQuantity() {
        Map<Quantity, Supplier<Object>> refused = Map.ofEntries(
                Map.entry(Quantity.HIGHEST_ORDER, () -> new TaylorSettings(TaylorSettings.MAX_HIGHEST_ORDER + 1, 0,
                        TaylorExpansion.AUTO)),
                Map.entry(Quantity.TAYLOR_TOLERANCE, () -> new TaylorSettings(30, 1, TaylorExpansion.AUTO)),
                Map.entry(Quantity.WINDOW_RADIUS, () -> new WindowSettings(WindowSettings.MAX_RADIUS + 1, false, 0, WindowPlacement.AVERAGED)),
                Map.entry(Quantity.PQ_REPLICAS, () -> new WindowSettings(1, false, -1, WindowPlacement.AVERAGED)),
                Map.entry(Quantity.LAMBDA_MIN, () -> new SpectralSettings(300, 780, 5)),
                Map.entry(Quantity.LAMBDA_MAX, () -> new SpectralSettings(500, 450, 5)),
                Map.entry(Quantity.LAMBDA_STEP, () -> new SpectralSettings(380, 780, 0)),
                Map.entry(Quantity.COHERENCE_LENGTH, () -> IlluminationSettings.ofCoherenceLength(0, 1.5)),
                Map.entry(Quantity.REFRACTIVE_INDEX, () -> new IlluminationSettings(16, 0.9)),
                Map.entry(Quantity.BAKED_SAMPLES, () -> new GpuTableSettings(TermFormat.RG32F, 1, 0)));
        for (var entry : refused.entrySet()) {
            InvalidSettingException e = assertThrows(InvalidSettingException.class, () -> entry.getValue().get(),
                    entry.getKey().toString());
            assertEquals(entry.getKey(), e.quantity());
            assertTrue(e.getMessage().toLowerCase(java.util.Locale.ROOT).contains(entry.getKey().words().toLowerCase(
                    java.util.Locale.ROOT)) || e.getMessage().contains("got"), e.getMessage());
            assertTrue(!e.getMessage().contains("--"), "a domain message names no option: " + e.getMessage());
        }
    }

    @Test
    void theEdgesOfEachRangeAreAccepted() {
        new TaylorSettings(TaylorSettings.MAX_HIGHEST_ORDER, 0, TaylorExpansion.AUTO);
        new TaylorSettings(0, 0, TaylorExpansion.AUTO);
        new WindowSettings(WindowSettings.MAX_RADIUS, false, WindowSettings.MAX_PQ_REPLICAS, WindowPlacement.AVERAGED);
        new SpectralSettings(SpectralSettings.LOWEST_NM, SpectralSettings.HIGHEST_NM, SpectralSettings.MAX_STEP_NM);
        new IlluminationSettings(IlluminationSettings.MAX_COHERENCE_LENGTH_UM / 4, IlluminationSettings.MAX_REFRACTIVE_INDEX);
        new GpuTableSettings(TermFormat.RG8, BakedGrid.MAX_SAMPLES, 2);
        assertThrows(IllegalArgumentException.class, () -> START.with(b -> b.expansion(null)));
    }

    /**
     * The user's choice of a method that cannot take the rigorous orders is refused; the program's own switch to such a
     * method (a table for the environment, the preview) draws it with the scalar orders, and a switch to a method that
     * takes them keeps them.
     */
    @Test
    void aMethodTheProgramDrawsByKeepsTheRigorousOrdersOnlyWhereItTakesThem() {
        BrdfSettings rigorous = BrdfSettings.thesis(Variant.LOBES).with(b -> b.rigorous(
                RigorousSettings.DEFAULT.withOrders(OrderWeights.RIGOROUS)));
        InvalidSettingException refused = assertThrows(InvalidSettingException.class,
                () -> rigorous.with(b -> b.variant(Variant.BAKED)));
        assertEquals(Quantity.ORDERS, refused.quantity());
        assertEquals(OrderWeights.SCALAR, rigorous.with(b -> b.drawnBy(Variant.BAKED)).rigorous().orders());
        assertEquals(Variant.BAKED, rigorous.with(b -> b.drawnBy(Variant.BAKED)).variant());
        assertEquals(OrderWeights.SCALAR, rigorous.with(b -> b.drawnBy(Variant.FLSS)).rigorous().orders());
        assertEquals(OrderWeights.RIGOROUS, rigorous.with(b -> b.drawnBy(Variant.LOBES)).rigorous().orders());
    }
}
