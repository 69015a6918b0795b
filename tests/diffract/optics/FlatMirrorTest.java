package diffract.optics;

import diffract.colour.Srgb;
import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.GainFactor;
import diffract.optics.illumination.IlluminationSettings;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** A flat patch is a mirror: D65 white in the specular direction, nothing elsewhere (relative BRDF). */
class FlatMirrorTest {
    private static final HeightField FLAT = SyntheticPatches.flat(64, 64, 0.1).meanSubtracted();
    private static final TaylorTerms TERMS = TaylorTermComputer.compute(FLAT, 4, Reporter.SILENT);

    static java.util.stream.Stream<Variant> cpuMethods() {
        return java.util.Arrays.stream(Variant.values()).filter(Variant::runsOnCpu);
    }

    private static DiffractionBrdf brdf(Variant variant) {
        return DiffractionBrdf.create(BrdfSettings.thesis(variant).with(b -> b.highestOrder(4)), FLAT, TERMS);
    }

    @ParameterizedTest
    @MethodSource("cpuMethods") // the baked table is GPU only
    void normalIncidenceSpecularIsExactlyD65White(Variant variant) {
        Direction normal = new Direction(0, 0, 1);
        Xyz xyz = brdf(variant).xyz(normal, normal);
        assertEquals(1.0, xyz.y(), 1e-12);
        assertEquals(0.9505, xyz.x(), 1e-3);
        assertEquals(1.0888, xyz.z(), 1e-3);
        double[] rgb = Srgb.linearFromXyz(xyz);
        for (double c : rgb) {
            assertEquals(1.0, c, 1e-3);
        }
    }

    @ParameterizedTest
    @MethodSource("cpuMethods") // the baked table is GPU only
    void obliqueSpecularIsWhiteScaledByTheGainFactor(Variant variant) {
        Direction wi = Direction.fromSphericalDeg(40, 30);
        Direction wr = wi.specular();
        Xyz xyz = brdf(variant).xyz(wi, wr);
        IlluminationSettings illumination = BrdfSettings.thesis(variant).illumination();
        // the rigorous method's mirror is Fresnel's exact reflectance, as Rayleigh-Rice's factor is at the specular
        double gain = GainFactor.gainTimesShadowing(wi, wr, illumination.refractiveIndex(), illumination.gain());
        assertEquals(gain, xyz.y(), 1e-12);
        Xyz white = brdf(variant).xyz(new Direction(0, 0, 1), new Direction(0, 0, 1));
        assertEquals(white.x() * gain, xyz.x(), 1e-12);
        assertEquals(white.z() * gain, xyz.z(), 1e-12);
    }

    @ParameterizedTest
    @MethodSource("cpuMethods") // the baked table is GPU only
    void nothingLeavesAwayFromTheSpecularDirection(Variant variant) {
        Direction wi = Direction.fromSphericalDeg(20, 0);
        // 40 degrees away from the mirror direction: |s| > 4 texels for every visible wavelength
        Direction wr = Direction.fromSphericalDeg(20, 180 + 120);
        Xyz xyz = brdf(variant).xyz(wi, wr);
        assertEquals(0.0, xyz.y(), 1e-12);
        assertEquals(0.0, brdf(variant).relative(wi, wr, 550), 1e-12);
    }
}
