package diffract.app;

import diffract.colour.D65;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.Methods;
import diffract.optics.spectra.PatchSpectrum;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.optics.settings.WavelengthSampling;
import diffract.jrtr.GlTestSupport;
import diffract.render.GpuMethods;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A method is one class: a toy method, defined here and registered from the tests ({@link Methods#register}), is
 * found by its label, drawn by {@code brdfmap} on the CPU and refused, naming itself, where it has no shader
 * (the GPU, a scene), without a line changed elsewhere; given a shader and its GPU side, it draws on the GPU, in a
 * scene and in the bench too.
 */
class ToyMethodTest {
    /** |P|^2 the same at every (u, v, w) and wavelength: white light, reflected as white times the gain factor. */
    static final class ConstantMethod implements Variant {
        static final double POWER = 0.02;

        private final boolean gpu;

        /** @param gpu whether it claims to run on the GPU (a shader and a GPU side are registered for it) */
        ConstantMethod(boolean gpu) {
            this.gpu = gpu;
        }

        @Override
        public String label() {
            return "constant";
        }

        @Override
        public java.util.Set<Capability> capabilities() {
            return gpu ? java.util.EnumSet.of(Capability.CPU, Capability.GPU, Capability.READS_TERMS)
                    : java.util.EnumSet.of(Capability.CPU, Capability.READS_TERMS);
        }

        @Override
        public DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
            PatchSpectrum flat = new PatchSpectrum() {
                @Override
                public double power(double u, double v, double w, double lambdaUm) {
                    return POWER;
                }

                @Override
                public double extentXUm() {
                    return meanSubtracted.cols() * meanSubtracted.pixelSizeXUm();
                }

                @Override
                public double extentYUm() {
                    return meanSubtracted.rows() * meanSubtracted.pixelSizeYUm();
                }
            };
            SpectralSettings s = settings.spectral();
            return new DiffractionBrdf(flat, WavelengthSampling.uniform(s.lambdaMinNm(), s.lambdaMaxNm(),
                    s.lambdaStepNm(), s.normalisation()), settings.illumination().refractiveIndex(),
                    settings.illumination().gain());
        }
    }

    /**
     * With a shader ({@code tests/shaders/diffraction/constant.frag}, on the test classpath) and its GPU side
     * registered ({@link GpuMethods#register}: the one texture it reads), the same toy draws on the GPU as on the
     * CPU, through {@code brdfmap}, a scene of its material renders and the bench's sweep measures it.
     */
    @Test
    void aMethodWithAShaderDrawsOnTheGpuAsOnTheCpu(@TempDir Path dir) throws IOException {
        GlTestSupport.assumeOffscreenGl();
        ConstantMethod toy = new ConstantMethod(true);
        Methods.register(toy);
        GpuMethods.register(toy, (m, textures, settings) -> m.setTexture("uniformNodeTable",
                textures.uniformNodeTable()));
        try {
            Path cpuPng = dir.resolve("cpu.png");
            Path gpuPng = dir.resolve("gpu.png");
            for (String engine : new String[] {"cpu", "gpu"}) {
                Object[] drawn = CliTest.run("brdfmap", "--synthetic", "blazed", "--variant", "constant", "--engine",
                        engine, "--theta-i", "30", "--size", "16", "--light-size-deg", "0", "-q", "-o",
                        (engine.equals("cpu") ? cpuPng : gpuPng).toString());
                assertEquals(0, drawn[0], engine + ": " + drawn[1] + " / " + drawn[2]);
            }
            BufferedImage cpu = ImageIO.read(cpuPng.toFile());
            BufferedImage gpu = ImageIO.read(gpuPng.toFile());
            int grey = 0;
            for (int y = 0; y < 16; y++) {
                for (int x = 0; x < 16; x++) {
                    int a = cpu.getRGB(x, y);
                    int b = gpu.getRGB(x, y);
                    for (int shift = 0; shift <= 16; shift += 8) {
                        assertEquals(a >> shift & 0xff, b >> shift & 0xff, 1, "pixel " + x + ", " + y);
                    }
                    grey += (a & 0xff) > 0 ? 1 : 0;
                }
            }
            assertTrue(grey > 100, grey + " lit pixels");
            // and in a scene: a plane of the toy material under the scene's light
            Path scene = dir.resolve("constant-plane.json");
            java.nio.file.Files.writeString(scene, """
                    {"image": {"width": 32, "height": 24}, "camera": {"eye": [0, 0, 3.5]},
                     "light": {"thetaDeg": 30, "phiDeg": 0}, "shape": {"kind": "plane"},
                     "material": {"patch": {"procedural": "blazed"}, "variant": "constant", "exposure": 40}}
                    """);
            Path rendered = dir.resolve("scene.png");
            Object[] drawn = CliTest.run("render", scene.toString(), "-q", "-o", rendered.toString());
            assertEquals(0, drawn[0], drawn[1] + " / " + drawn[2]);
            BufferedImage picture = ImageIO.read(rendered.toFile());
            int centre = picture.getRGB(16, 12);
            int r = centre >> 16 & 0xff;
            int g = centre >> 8 & 0xff;
            int b = centre & 0xff;
            // lit, and white light reflected white: grey
            assertTrue(g > 100 && Math.abs(r - g) <= 3 && Math.abs(b - g) <= 3, "the plane's centre: " + r + " " + g
                    + " " + b);
            // and in the bench's sweep: a row of its own, timed and compared with the reference
            Path bench = dir.resolve("bench");
            Object[] swept = CliTest.run("bench", "--variants", "constant", "--patches", "blazed", "--sizes", "16",
                    "--error-size", "16", "--large-size", "16", "--frames", "10", "--no-cache", "-q", "-o",
                    bench.toString());
            assertEquals(0, swept[0], swept[1] + " / " + swept[2]);
            String results = java.nio.file.Files.readString(bench.resolve("results.csv"));
            assertTrue(results.contains("constant"), results);
            diffract.util.TestReport.line(ToyMethodTest.class, "the toy in the bench's sweep:\n" + results);
        } finally {
            GpuMethods.unregister(toy);
            Methods.unregister(toy);
        }
    }

    @Test
    void aMethodRegisteredFromTheTestsIsFoundDrawnAndRefusedByItsName(@TempDir Path dir) throws IOException {
        ConstantMethod toy = new ConstantMethod(false);
        Methods.register(toy);
        try {
            assertSame(toy, Variant.parse("Constant"));
            HeightField patch = SyntheticPatches.blazed(2.5, 0.13, 10, 4, 4).meanSubtracted();
            // its map through the API: every lit pixel D65's chromaticity, its luminance the gain factor's share
            DiffractionBrdf brdf = DiffractionBrdf.create(BrdfSettings.thesis(toy), patch, null);
            Direction wi = Direction.fromSphericalDeg(30, 0);
            float[] xyz = BrdfMap.xyz(brdf, wi, 16, Reporter.SILENT);
            diffract.colour.Xyz d65 = D65.whiteXyz();
            double[] white = {d65.x() / (d65.x() + d65.y() + d65.z()), d65.y() / (d65.x() + d65.y() + d65.z())};
            int lit = 0;
            for (int p = 0; p < 16 * 16; p++) {
                double sum = xyz[3 * p] + xyz[3 * p + 1] + xyz[3 * p + 2];
                if (sum > 0) {
                    lit++;
                    assertEquals(white[0], xyz[3 * p] / sum, 1e-4, "x at pixel " + p);
                    assertEquals(white[1], xyz[3 * p + 1] / sum, 1e-4, "y at pixel " + p);
                }
            }
            assertTrue(lit > 100, lit + " lit pixels");
            // through brdfmap on the CPU: a grey map inside the unit disk, black outside
            Path png = dir.resolve("constant.png");
            Object[] drawn = CliTest.run("brdfmap", "--synthetic", "blazed", "--variant", "constant", "--engine",
                    "cpu", "--theta-i", "30", "--size", "16", "--light-size-deg", "0", "-q", "-o", png.toString());
            assertEquals(0, drawn[0], (String) drawn[2]);
            BufferedImage map = ImageIO.read(png.toFile());
            int centre = map.getRGB(8, 8);
            int r = centre >> 16 & 0xff;
            int g = centre >> 8 & 0xff;
            int b = centre & 0xff;
            assertTrue(g > 0 && Math.abs(r - g) <= 3 && Math.abs(b - g) <= 3, "centre pixel " + r + " " + g + " " + b);
            assertEquals(0, map.getRGB(0, 0) & 0xffffff, "outside the unit disk");
            // where it has no shader it is refused by its own name
            Object[] gpu = CliTest.run("brdfmap", "--synthetic", "blazed", "--variant", "constant", "--engine",
                    "gpu", "--size", "16", "-o", dir.resolve("gpu.png").toString());
            assertEquals(2, gpu[0]);
            assertTrue(((String) gpu[2]).contains("the constant variant runs on the CPU only"), (String) gpu[2]);
        } finally {
            Methods.unregister(toy);
        }
        Object[] gone = CliTest.run("brdfmap", "--synthetic", "blazed", "--variant", "constant", "-o",
                dir.resolve("gone.png").toString());
        assertEquals(2, gone[0]);
        assertTrue(((String) gone[2]).contains("unknown variant 'constant'"), (String) gone[2]);
    }
}
