package diffract.render;

import diffract.optics.BrdfSettings;
import diffract.optics.HeightField;
import diffract.optics.Variant;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Issue #5, part 2 on the GPU: with the Taylor loop's early stop (tolerance 1e-4) and the automatic window radius,
 * the GPU map still equals the CPU map of the same settings, in the style and with the tolerance of
 * {@link GpuCpuAgreementTest} (mean CIEDE2000 &lt;= 1, p99 &lt;= 3; the shader's stop order is the CPU's recurrence
 * in float32, so both drop the same terms except where rounding puts the bound on the other side of the tolerance,
 * which changes P by at most the tolerance times the window's weight). Tolerance 0 and the fixed radius are the
 * unchanged thesis path, held by GpuCpuAgreementTest and the golden images.
 */
@Tag("gl")
class GpuEarlyStopTest {
    @ParameterizedTest
    @EnumSource(value = Variant.class, names = {"FLSS", "PQ"})
    void earlyStopAndAutomaticWindowMatchTheCpu(Variant variant) {
        for (HeightField patch : new HeightField[] {RenderTestSupport.BLAZED, RenderTestSupport.ELAPHE_LIKE}) {
            BrdfSettings settings = RenderTestSupport.settings(variant).withTaylorTolerance(1e-4)
                    .withAutomaticWindowRadius(true);
            GpuCpuAgreementTest.assertGpuEqualsCpu(patch, settings, variant + " early stop + automatic window,");
        }
    }
}
