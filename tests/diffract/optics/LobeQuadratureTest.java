package diffract.optics;

import diffract.optics.settings.InvalidSettingException;
import org.junit.jupiter.api.Test;

import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The knobs by name, as the command line and scene files give them. */
class LobeQuadratureTest {
    @Test
    void theKnobsByNameGiveTheQuadratureBack() {
        LobeQuadrature q = new LobeQuadrature(1e-3, 2, 4, 6, 2, 5, 1e-5, 1e-3, 4);
        assertEquals(LobeQuadrature.KNOBS, java.util.List.copyOf(q.knobs().keySet()));
        assertEquals(q, LobeQuadrature.DEFAULT.withKnobs(q.knobs()));
        LobeQuadrature changed = q.withKnobs(Map.of("reachSigmas", 8.0, "lightNodes", 7.0));
        assertEquals(8, changed.reachSigmas());
        assertEquals(7, changed.lightNodes());
        assertEquals(q.nodesPerSigma(), changed.nodesPerSigma(), "the knobs not named keep their values");
    }

    @Test
    void theCutoffByNameIsTheOneAsked() {
        LobeQuadrature shown = LobeQuadrature.DEFAULT.shownAt(300);
        assertEquals(LobeQuadrature.DEFAULT.cutoff() / 10, shown.cutoff(), 1e-18);
        assertEquals(LobeQuadrature.DEFAULT.cutoff(), shown.knobs().get("cutoff"));
    }

    @Test
    void unknownKnobsFractionalNodesAndValuesOutOfRangeAreRefused() {
        String unknown = assertThrows(InvalidSettingException.class,
                () -> LobeQuadrature.DEFAULT.withKnobs(Map.of("reach", 5.0))).getMessage();
        assertTrue(unknown.contains("no knob 'reach'") && unknown.contains("reachSigmas"), unknown);
        String fractional = assertThrows(InvalidSettingException.class,
                () -> LobeQuadrature.DEFAULT.withKnobs(Map.of("lightNodes", 2.5))).getMessage();
        assertTrue(fractional.contains("whole number"), fractional);
        String range = assertThrows(InvalidSettingException.class,
                () -> LobeQuadrature.DEFAULT.withKnobs(Map.of("reachSigmas", 40.0))).getMessage();
        assertTrue(range.contains("2..10"), range);
    }
}
