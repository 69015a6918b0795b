package diffract.render;

import diffract.colour.Srgb;
import diffract.jrtr.GlTestSupport;
import diffract.optics.illumination.BoxedEdge;
import diffract.optics.BrdfSettings;
import diffract.optics.numerics.ErrorFunction;
import diffract.optics.settings.PixelFilter;
import diffract.optics.Variant;
import diffract.util.TestReport;
import org.junit.jupiter.api.Test;

import java.util.Map;
import java.util.TreeMap;
import java.util.function.DoubleBinaryOperator;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The shaders' small functions against their Java twins, one function at a time on a grid of inputs
 * ({@link GlslFunctions}): float32 on the GPU against double on the CPU at the same inputs. Each bound is a few times
 * the float32 error measured here (printed to the test report); a slip of 1e-4 in a function, or the wrong twin, fails.
 */
class GlslTwinsTest {
    private static final String SRGB = "engine/srgb.glsl";
    /** lobes_footprint.glsl, within the lobes method's spectrum (which defines the functions it declares). */
    private static final String FOOTPRINT = "diffraction/lobes_spectrum.glsl";

    /** The defines a BRDF map of the lobes method under a disc light compiles its footprint functions with. */
    private static Map<String, String> footprintDefines() {
        BrdfSettings lobes = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX));
        Map<String, String> defines = new TreeMap<>(DiffractionShaders.defines(lobes, DiffractionShaders.Target.BRDF_MAP,
                false, false));
        defines.put("LOBES_BOX", "1");
        defines.put("LIGHT_DISC", "1");
        return defines;
    }

    private static GlslFunctions.Comparison check(String include, Map<String, String> defines, String expression,
                                                 int nx, int ny, double[] xRange, double[] yRange,
                                                 DoubleBinaryOperator twin, double bound) {
        GlslFunctions.Comparison c = GlslFunctions.compare(GlslFunctions.evaluate(include, defines, expression, nx, ny,
                xRange[0], xRange[1], yRange[0], yRange[1]), twin);
        TestReport.line(GlslTwinsTest.class, expression + ": " + c + " (bound " + bound + ")");
        assertTrue(c.maxAbsError() <= bound, expression + ": " + c);
        return c;
    }

    @Test
    void srgbEncodingAndDecodingAreSrgbs() {
        GlTestSupport.assumeOffscreenGl();
        double[] none = {0, 0};
        check(SRGB, Map.of(), "srgbEncode(x)", 513, 1, new double[] {-0.05, 1.05}, none,
                (x, y) -> Srgb.encode(x), 2e-6);
        check(SRGB, Map.of(), "srgbDecode(x)", 513, 1, new double[] {0, 1}, none, (x, y) -> Srgb.decode(x), 2e-6);
    }

    @Test
    void theFastErrorFunctionsAreErrorFunctions() {
        GlTestSupport.assumeOffscreenGl();
        Map<String, String> defines = footprintDefines();
        double[] none = {0, 0};
        check(FOOTPRINT, defines, "erfcPositive(x)", 601, 1, new double[] {0, 6}, none,
                (x, y) -> ErrorFunction.fastErfc(x), 1e-6);
        // and the polynomial itself against the accurate erfc: Abramowitz and Stegun's 1.5e-7 plus float32
        check(FOOTPRINT, defines, "erfcPositive(x)", 601, 1, new double[] {0, 6}, none,
                (x, y) -> ErrorFunction.erfc(x), 1.5e-7 + 1e-6);
        check(FOOTPRINT, defines, "normalCdf(x)", 801, 1, new double[] {-8, 8}, none,
                (x, y) -> 0.5 * ErrorFunction.erfc(-x / Math.sqrt(2)), 1.5e-7 + 1e-6);
        // an interval [a, b] with a <= b, as lobeAxis passes it (the shader's selects assume the order)
        check(FOOTPRINT, defines, "massInInterval(min(x, y), max(x, y))", 81, 81, new double[] {-4, 4},
                new double[] {-4, 4}, (x, y) -> ErrorFunction.fastMassInInterval(Math.min(x, y), Math.max(x, y)), 2e-6);
    }

    /**
     * The box-averaged edge (BoxedEdge.average with the shader's erfc) over its three branches: a point, one uniform
     * and the trapezoid, whose differences of Psi_2 divided by 4 a b are where float32 loses most.
     */
    @Test
    void theBoxAveragedEdgeIsBoxedEdges() {
        GlTestSupport.assumeOffscreenGl();
        Map<String, String> defines = footprintDefines();
        for (double ha : new double[] {1e-4, 0.05, 0.3, 2}) {
            String expression = String.format(java.util.Locale.ROOT, "boxedNormalCdf(x, %s, y, 0.5)", (float) ha);
            double haFloat = (float) ha;
            check(FOOTPRINT, defines, expression, 81, 41, new double[] {-3, 3}, new double[] {1e-4, 1.5},
                    (x, y) -> BoxedEdge.average(x, haFloat, y, 0.5, true), 2e-5);
        }
    }

    /** The harness fails what it should: the wrong twin, and a function off by 1e-4 of its value. */
    @Test
    void aWrongTwinOrASlipFails() {
        GlTestSupport.assumeOffscreenGl();
        double[] none = {0, 0};
        GlslFunctions.Comparison wrongTwin = GlslFunctions.compare(GlslFunctions.evaluate(SRGB, Map.of(),
                "srgbEncode(x)", 65, 1, 0, 1, 0, 0), (x, y) -> Srgb.decode(x));
        assertTrue(wrongTwin.maxAbsError() > 0.1, wrongTwin.toString());
        GlslFunctions.Comparison slip = GlslFunctions.compare(GlslFunctions.evaluate(FOOTPRINT, footprintDefines(),
                "erfcPositive(x) * 1.0001", 65, 1, 0, 1, 0, 0), (x, y) -> ErrorFunction.fastErfc(x));
        assertTrue(slip.maxAbsError() > 1e-5 && slip.maxAbsError() < 2e-4, slip.toString());
    }
}
