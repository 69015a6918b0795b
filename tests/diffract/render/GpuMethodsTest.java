package diffract.render;

import diffract.optics.Methods;
import diffract.optics.Variant;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Every registered method that runs on the GPU has a GPU side; a CPU-only one has none, and the refusal names it. */
class GpuMethodsTest {
    @Test
    void everyMethodThatRunsOnTheGpuHasItsGpuSide() {
        int gpu = 0;
        for (Variant method : Methods.all()) {
            if (method.runsOnGpu()) {
                assertNotNull(GpuMethods.of(method), method.label());
                gpu++;
            }
        }
        assertTrue(gpu >= 5, "FLSS, NMM, PQ, baked and lobes at least: " + gpu);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> GpuMethods.of(Variant.REFERENCE));
        assertTrue(e.getMessage().contains(Variant.REFERENCE.label()), e.getMessage());
    }
}
