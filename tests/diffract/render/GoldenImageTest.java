package diffract.render;

import diffract.colour.ColourPath;
import diffract.colour.Xyz;
import diffract.jrtr.textures.FloatTextureArray;
import diffract.jrtr.GlTestSupport;
import diffract.optics.maps.AutoExposure;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.BrdfSettings;
import diffract.optics.Variant;
import diffract.util.ImageFiles;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;


/**
 * Screenshot regression: GPU BRDF maps (256 x 256, theta_i = 30 degrees, settings of {@link RenderTestSupport})
 * of the blazed grating and the Elaphe-like patch for each variant, displayed as the CLI displays them (auto
 * exposure from the map itself, {@link ColourPath#SRGB}, 8-bit PNG), against the PNGs in {@code tests/goldens/}.
 *
 * <p>Tolerance: a pixel matches when no channel differs by more than {@value #CHANNEL_TOLERANCE} of 255, and at most
 * {@value #PIXEL_BUDGET_PERCENT} % of the pixels may fail. On one machine llvmpipe is deterministic (measured: 0
 * differing pixels over repeated runs). Another Mesa or LLVM version may evaluate sin, exp and pow a few ulps
 * differently and reassociate sums: a relative change near 1e-6, which moves an 8-bit value by at most one step
 * where it lies on a rounding boundary (hence 2 steps of tolerance); a lookup that lands on a half-texel tie
 * (floor(s + 0.5)) or a pixel at the edge of a sharp order can change more, and those few pixels are what the
 * budget (0.5 %, 327 pixels) absorbs. A real regression (a sign, a wrong texel, a missing term) changes whole orders:
 * thousands of pixels by tens of steps.
 *
 * <p>On failure the rendered picture and an amplified difference (|a - b| x 16) go to {@code target/golden-diffs/}
 * ({@link GoldenImages}).
 * Regenerate the goldens after an intended change with
 * {@code xvfb-run -a mvn test -Dtest=GoldenImageTest -Ddiffract.updateGoldens=true}.
 */
@Tag("gl")
class GoldenImageTest {
    static final int SIZE = 256;
    static final int CHANNEL_TOLERANCE = 2;
    static final double PIXEL_BUDGET_PERCENT = 0.5;
    static final Path GOLDENS = Path.of("tests", "goldens");
    static final Path DIFFS = GoldenImages.DIFFS;
    static final int BAKED_UV_SAMPLES = 129;
    static final int BAKED_W_SAMPLES = 9;

    static Stream<Arguments> scenes() {
        Stream.Builder<Arguments> scenes = Stream.builder();
        for (HeightField patch : new HeightField[] {RenderTestSupport.BLAZED, RenderTestSupport.ELAPHE_LIKE}) {
            for (Variant variant : new Variant[] {Variant.FLSS, Variant.NMM, Variant.PQ, Variant.LOBES,
                    Variant.BAKED}) {
                scenes.add(Arguments.of(RenderTestSupport.name(patch) + "-" + variant.label() + "-30", patch, variant));
            }
        }
        return scenes.build();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void gpuBrdfMapMatchesItsGolden(String name, HeightField patch, Variant variant) throws IOException {
        GlTestSupport.assumeOffscreenGl();
        Direction wi = RenderTestSupport.light(patch, 30);
        float[] xyz;
        BrdfSettings settings = RenderTestSupport.settings(variant);
        if (variant == Variant.BAKED) {
            // a table of 129 x 129 x 9 samples bakes in seconds on a software rasteriser and still shows every order
            settings = settings.with(b -> b.bakedSamples(BAKED_UV_SAMPLES, BAKED_W_SAMPLES));
        }
        try (GpuBrdfMap gpu = new GpuBrdfMap(RenderTestSupport.terms(patch), settings)) {
            xyz = gpu.xyz(wi, SIZE);
        }
        Path actualPng = DIFFS.resolve(name + "-actual.png");
        Files.createDirectories(DIFFS);
        ImageFiles.writePng(actualPng, display(xyz, wi), SIZE, SIZE, 3);
        GoldenImages.assertMatches(name, actualPng, GOLDENS.resolve(name + ".png"), CHANNEL_TOLERANCE,
                PIXEL_BUDGET_PERCENT);
    }

    /** As the CLI: auto exposure (brightest diffracted pixel to Y = 1), then ColourPath.SRGB. */
    static float[] display(float[] xyz, Direction wi) {
        double exposure = AutoExposure.ofXyz(xyz, wi, SIZE);
        float[] rgb = new float[xyz.length];
        for (int p = 0; p < xyz.length; p += 3) {
            float[] c = ColourPath.SRGB.displayRgb(new Xyz(xyz[p], xyz[p + 1], xyz[p + 2]).scaled(exposure));
            System.arraycopy(c, 0, rgb, p, 3);
        }
        return rgb;
    }
}
