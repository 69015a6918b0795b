package diffract.optics;

import org.junit.jupiter.api.Test;

import java.lang.reflect.RecordComponent;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.UnaryOperator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

/** The with-methods change their own components and carry every other one, the expansion mode included. */
class BrdfSettingsTest {
    private static final BrdfSettings START = new BrdfSettings(Variant.NMM, 12, 2, 400, 700, 10, 3.0, 1.4, 2, 1e-5,
            true, 64, 9, TaylorEvaluation.Mode.CENTRED);

    @Test
    void eachWithMethodChangesOnlyItsComponents() throws Exception {
        Map<String, UnaryOperator<BrdfSettings>> edits = Map.ofEntries(
                Map.entry("variant", s -> s.withVariant(Variant.PQ)),
                Map.entry("highestOrder", s -> s.withHighestOrder(20)),
                Map.entry("windowRadius", s -> s.withWindowRadius(3)),
                Map.entry("lambdaStepNm", s -> s.withLambdaStepNm(1)),
                Map.entry("lambdaMinNm lambdaMaxNm", s -> s.withLambdaRangeNm(380, 780)),
                Map.entry("sigmaSpatialUm", s -> s.withSigmaSpatialUm(16.25)),
                Map.entry("taylorTolerance", s -> s.withTaylorTolerance(0)),
                Map.entry("automaticWindowRadius", s -> s.withAutomaticWindowRadius(false)),
                Map.entry("bakedUvSamples bakedWSamples", s -> s.withBakedSamples(128, 13)),
                Map.entry("expansion", s -> s.withExpansion(TaylorEvaluation.Mode.PLAIN)));
        for (var edit : edits.entrySet()) {
            BrdfSettings changed = edit.getValue().apply(START);
            List<String> differing = new ArrayList<>();
            for (RecordComponent c : BrdfSettings.class.getRecordComponents()) {
                if (!c.getAccessor().invoke(START).equals(c.getAccessor().invoke(changed))) {
                    differing.add(c.getName());
                }
            }
            assertEquals(List.of(edit.getKey().split(" ")), differing, edit.getKey());
        }
    }

    @Test
    void theOriginalNineArgumentsMeanTheAutomaticExpansionAndNoneIsRefused() {
        assertEquals(TaylorEvaluation.Mode.AUTO, BrdfSettings.thesis(Variant.FLSS).expansion());
        assertThrows(IllegalArgumentException.class, () -> START.withExpansion(null));
    }
}
