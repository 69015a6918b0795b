package diffract.render;

import diffract.util.TestReport;
import diffract.colour.SpectralIntegrator;
import diffract.colour.Xyz;
import diffract.jrtr.textures.FloatTexture3D;
import diffract.jrtr.GlTestSupport;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.spectra.PatchSpectrum;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.optics.settings.WavelengthSampling;
import diffract.util.Reporter;
import diffract.util.TestCache;
import diffract.util.UserInputException;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The BAKED variant: FLSS's spectral XYZ(u, v, w) tabulated on the GPU and looked up trilinearly.
 * Settings as the other GPU tests ({@link RenderTestSupport#settings}: 30 terms, 3 x 3, 5 nm, 4 sigma_s = 10 um),
 * tables of 129 x 129 (u, v) samples (odd, so u = v = 0 is a sample) and the automatic w resolution.
 */
@Tag("gl")
class BakedVariantTest {
    static final int SIZE = 64;
    static final int UV_SAMPLES = 129;

    @TempDir
    java.nio.file.Path cacheDir;
    /** An empty disk cache per test: the tests count bakes, which a table stored by an earlier run would save. */
    private TestCache cache;

    @BeforeEach
    void ownCache() {
        cache = TestCache.at(cacheDir);
    }

    @AfterEach
    void backToTheBuildsCache() {
        cache.close();
    }

    static BrdfSettings baked() {
        return RenderTestSupport.settings(Variant.BAKED).with(b -> b.bakedSamples(UV_SAMPLES, 0));
    }

    /**
     * At its samples the table is FLSS: the bake (float32 FLSS on the GPU) equals the CPU's double FLSS spectral
     * sum sum_j |P(lambda_j)|^2 weights_j at every reachable sample of a 17 x 17 x 3 table, to 2e-4 of the
     * table's largest value plus 2e-4 relative (the float32 Taylor sum's cancellation, see GpuCpuAgreementTest;
     * measured: printed). Samples beyond the reachable half-ball |(u, v, w)| <= 2 (plus a cell) are 0.
     */
    @Test
    void tableSamplesAreTheCpuFlssSpectralSums() {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        TaylorTerms terms = RenderTestSupport.terms(patch);
        BrdfSettings settings = RenderTestSupport.settings(Variant.FLSS).with(b -> b.bakedSamples(17, 3));
        BakedTable table = BakedTable.bake(terms, settings, Variant.FLSS, FloatTexture3D.Precision.FLOAT32, Reporter.SILENT);
        PatchSpectrum spectrum = DiffractionBrdf.create(settings, patch, terms).spectrum();
        WavelengthSampling sampling = WavelengthSampling.uniform(380, 780, 5);
        BakedGrid grid = table.grid();
        double largest = 0;
        for (float v : table.values()) {
            largest = Math.max(largest, v);
        }
        double worst = 0;
        int compared = 0;
        // the bake leaves out samples beyond the half-ball of radius 2 plus one cell diagonal (baked.frag)
        double cellDiagonal = Math.sqrt(2 * Math.pow(4.0 / (grid.uvSamples() - 1), 2)
                + Math.pow(2.0 / (grid.wSamples() - 1), 2));
        for (int k = 0; k < grid.wSamples(); k++) {
            for (int j = 0; j < grid.uvSamples(); j++) {
                for (int i = 0; i < grid.uvSamples(); i++) {
                    double u = grid.uv(i);
                    double v = grid.uv(j);
                    double w = grid.w(k);
                    float[] gpu = table.xyzAt(i, j, k);
                    if (Math.sqrt(u * u + v * v + w * w) > 2.0 + cellDiagonal + 1e-3) {
                        assertEquals(0f, gpu[1], "unreachable sample " + i + ", " + j + ", " + k);
                        continue;
                    }
                    Xyz cpu = spectralXyz(spectrum, sampling, u, v, w);
                    double[] expected = {cpu.x(), cpu.y(), cpu.z()};
                    for (int c = 0; c < 3; c++) {
                        double error = Math.abs(gpu[c] - expected[c]);
                        worst = Math.max(worst, error / largest);
                        assertTrue(error <= 2e-4 * largest + 2e-4 * expected[c], "sample (" + u + ", " + v + ", " + w
                                + ") channel " + c + ": GPU " + gpu[c] + ", CPU " + expected[c]);
                    }
                    compared++;
                }
            }
        }
        TestReport.printf(BakedVariantTest.class, "baked samples vs CPU FLSS: %d samples, largest error %.2e of the table's peak %.3g%n",
                compared, worst, largest);
        assertTrue(compared > 300);
    }

    /**
     * Maps of the baked variant against the CPU's FLSS and reference maps (64 x 64, theta_i 0, 45, 75), through
     * the exposure AutoExposure picks from the CPU map. What the table loses is trilinear interpolation of orders
     * that are Gaussians of sigma = lambda / (2 pi sigma_s) = 0.024..0.050 in (u, v), sampled every
     * 4 / 128 = 0.031: about h^2 / (8 sigma^2) = 0.05..0.2 of a peak, where an order is narrow, i.e. the pictures are
     * the same with visibly softened narrow orders; FLSS's own distance to the reference is printed beside it.
     * Measured (llvmpipe): mean CIEDE2000 over the disk 0.36 to 0.51, over the lit pixels 2.4 to 5.3. The bounds
     * sit about half above the worst, for a GPU whose texture unit interpolates with 8-bit weights (CUDA's
     * documented linear filtering); a table of half the samples breaks both ({@link #aCoarserTableFailsTheBounds}).
     */
    static final double MAX_DISK_MEAN = 0.8;
    static final double MAX_LIT_MEAN = 7.5;

    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // bakes and draws maps of several methods: a long test
    void bakedMapsAgreeWithFlssAndTheReference() {
        GlTestSupport.assumeOffscreenGl();
        Worst worst = compareMaps(baked(), true, RenderTestSupport.BLAZED, RenderTestSupport.ELAPHE_LIKE);
        TestReport.printf(BakedVariantTest.class, "worst of %d maps: disk mean %.3f, lit mean %.3f%n", worst.maps,
                worst.diskMean, worst.litMean);
        assertTrue(worst.diskMean <= MAX_DISK_MEAN, "disk mean " + worst.diskMean);
        assertTrue(worst.litMean <= MAX_LIT_MEAN, "lit mean " + worst.litMean);
    }

    /**
     * The bounds catch a table that resolves the orders worse: half the samples along u and v (spacing 0.062, four
     * times the interpolation error where an order is narrow) breaks both on the blazed grating (measured: disk 0.93
     * to 1.21, lit 10.9 to 11.6; the Elaphe-like patch's are 1.12 to 1.39 and 5.4 to 7.9).
     */
    @Test
    void aCoarserTableFailsTheBounds() {
        GlTestSupport.assumeOffscreenGl();
        Worst coarse = compareMaps(RenderTestSupport.settings(Variant.BAKED).with(b -> b.bakedSamples(
                (UV_SAMPLES + 1) / 2, 0)), false, RenderTestSupport.BLAZED);
        TestReport.printf(BakedVariantTest.class, "a table of %d uv samples, worst of %d maps: disk mean %.3f, lit "
                + "mean %.3f%n", (UV_SAMPLES + 1) / 2, coarse.maps, coarse.diskMean, coarse.litMean);
        assertTrue(coarse.diskMean > MAX_DISK_MEAN, "disk mean " + coarse.diskMean);
        assertTrue(coarse.litMean > MAX_LIT_MEAN, "lit mean " + coarse.litMean);
    }

    /** The largest means over the patches and the three angles. */
    private record Worst(int maps, double diskMean, double litMean) {
        Worst with(BrdfMapDifference d) {
            return new Worst(maps + 1, Math.max(diskMean, d.disk().mean()), Math.max(litMean, d.lit().mean()));
        }
    }

    /**
     * Every map of {@code settings} on {@code patches} against FLSS (and, with {@code againstReference}, the
     * reference), reported.
     */
    private static Worst compareMaps(BrdfSettings settings, boolean againstReference, HeightField... patches) {
        Worst worst = new Worst(0, 0, 0);
        for (HeightField patch : patches) {
            TaylorTerms terms = RenderTestSupport.terms(patch);
            DiffractionBrdf flss = DiffractionBrdf.create(RenderTestSupport.settings(Variant.FLSS), patch, terms);
            DiffractionBrdf reference = DiffractionBrdf.create(RenderTestSupport.settings(Variant.REFERENCE), patch,
                    terms);
            try (GpuBrdfMap gpu = new GpuBrdfMap(terms, settings)) {
                for (double thetaI : new double[] {0, 45, 75}) {
                    Direction wi = RenderTestSupport.light(patch, thetaI);
                    float[] cpuFlss = BrdfMap.xyz(flss, wi, SIZE, Reporter.SILENT);
                    float[] actual = gpu.xyz(wi, SIZE);
                    BrdfMapDifference toFlss = RenderTestSupport.difference(cpuFlss, actual, SIZE, wi);
                    String where = "baked (" + settings.gpu().bakedUvSamples() + " uv) " + RenderTestSupport.name(patch)
                            + " theta_i " + thetaI;
                    TestReport.line(BakedVariantTest.class, where + " vs CPU flss: " + toFlss.summary());
                    assertTrue(toFlss.litPixels() >= 20, where + ": too few lit pixels");
                    worst = worst.with(toFlss);
                    if (againstReference) {
                        float[] cpuReference = BrdfMap.xyz(reference, wi, SIZE, Reporter.SILENT);
                        BrdfMapDifference toReference = RenderTestSupport.difference(cpuReference, actual, SIZE, wi);
                        BrdfMapDifference flssToReference = RenderTestSupport.difference(cpuReference, cpuFlss, SIZE,
                                wi);
                        TestReport.line(BakedVariantTest.class, where + " vs CPU reference: " + toReference.summary()
                                + "; flss vs reference: " + flssToReference.summary());
                        worst = worst.with(toReference);
                    }
                }
            }
        }
        return worst;
    }

    /**
     * Memory: the GPU table is uv^2 x w texels of RGB16F (6 bytes), the host keeps float32 RGB (12 bytes); the
     * cache bakes once per (patch, settings) and again for other settings.
     */
    @Test
    void memoryIsAccountedAndTheBakeIsCached() {
        GlTestSupport.assumeOffscreenGl();
        TaylorTerms terms = RenderTestSupport.terms(RenderTestSupport.BLAZED);
        BrdfSettings settings = RenderTestSupport.settings(Variant.BAKED).with(b -> b.bakedSamples(33, 0));
        BakedTables tables = new BakedTables(); // a pipeline's
        int before = tables.bakeCount() + tables.loadCount();
        DiffractionTextures first = DiffractionTextures.of(terms, settings, tables, Reporter.SILENT);
        DiffractionTextures second = DiffractionTextures.of(terms, settings, tables, Reporter.SILENT);
        assertEquals(before + 1, tables.bakeCount() + tables.loadCount(), "the same patch and settings bake once");
        assertTrue(first.baked() == second.baked());
        BakedTable table = first.baked();
        int w = BakedGrid.automaticWSamples(settings, terms.maxAbsHeightUm());
        assertEquals(33, table.grid().uvSamples());
        assertEquals(w, table.grid().wSamples());
        assertEquals(33L * 33 * w * 6, table.gpuBytes());
        assertEquals(33L * 33 * w * 12, table.hostBytes());
        assertEquals(table.gpuBytes(), first.tables().texture().gpuBytes());
        assertEquals(3 * 33 * 33 * w, table.values().length);
        DiffractionTextures.of(terms, settings.with(b -> b.lambdaStepNm(10)), tables, Reporter.SILENT);
        assertEquals(before + 2, tables.bakeCount() + tables.loadCount(), "other settings, another table");
        // the (u, v) resolution that would resolve the thesis' 65 um orders, and the automatic cap
        BrdfSettings thesis = BrdfSettings.thesis(Variant.BAKED);
        assertEquals(2151, BakedGrid.uvSamplesToResolve(thesis));
        assertEquals(BakedGrid.MAX_AUTOMATIC_UV_SAMPLES, BakedGrid.automaticUvSamples(thesis));
        assertEquals(332, BakedGrid.uvSamplesToResolve(RenderTestSupport.settings(Variant.BAKED)));
    }

    /**
     * Grazing light (theta_i = 89.9 degrees) and the exact specular direction are finite; at normal incidence the
     * specular pixel of an odd map (pixel (16, 16) of 33 is omega_r = (0, 0, 1), (u, v, w) = (0, 0, -2), a table
     * sample) equals the CPU's FLSS to half precision, 1e-3.
     */
    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // bakes a table: a long test
    void finiteAtGrazingLightAndExactAtTheSpecularSample() {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        TaylorTerms terms = RenderTestSupport.terms(patch);
        DiffractionBrdf flss = DiffractionBrdf.create(RenderTestSupport.settings(Variant.FLSS), patch, terms);
        try (GpuBrdfMap gpu = new GpuBrdfMap(terms, baked())) {
            for (double phi : new double[] {0, 90}) {
                float[] grazing = gpu.xyz(Direction.fromSphericalDeg(89.9, phi), 32);
                for (float v : grazing) {
                    assertTrue(Float.isFinite(v) && v >= 0, "at 89.9 degrees: " + v);
                }
            }
            Direction normal = Direction.fromSphericalDeg(0, 0);
            float[] map = gpu.xyz(normal, 33);
            for (float v : map) {
                assertTrue(Float.isFinite(v) && v >= 0, "at normal incidence: " + v);
            }
            Xyz expected = flss.xyz(normal, new Direction(0, 0, 1));
            int p = 3 * (16 * 33 + 16);
            assertTrue(expected.y() > 1e-3);
            assertEquals(expected.y(), map[p + 1], 1e-3 * expected.y(), "specular pixel");
            assertThrows(UserInputException.class, () -> gpu.monochromatic(normal, 550, 8));
        }
        assertThrows(UserInputException.class,
                () -> DiffractionBrdf.create(RenderTestSupport.settings(Variant.BAKED), patch, terms));
    }

    /**
     * The mesh path (surface.vert, 003 Algorithm 2) reads the same table: a square facing the camera, light from
     * straight above, so the centre pixel is the specular direction at normal incidence, (u, v, w) = (0, 0, -2), a
     * table sample: its display sRGB equals that of the CPU's FLSS there (to 2/255), and every pixel is in [0, 1].
     */
    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // bakes a table: a long test
    void surfacePathReadsTheTable() {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        TaylorTerms terms = RenderTestSupport.terms(patch);
        DiffractionTextures textures = DiffractionTextures.of(terms, baked());
        float exposure = 0.5f;
        float[] rgba = GpuFinitenessTest.render(DiffractionMaterials.surface(textures, baked(), exposure, null, 0),
                new javax.vecmath.Vector3f(0, 0, 1),
                diffract.jrtr.scenegraph.Shapes.rectangle("square", -1, -1, 1, 1, 0), 33);
        for (float v : rgba) {
            assertTrue(Float.isFinite(v) && v >= 0 && v <= 1, "surface value " + v);
        }
        DiffractionBrdf flss = DiffractionBrdf.create(RenderTestSupport.settings(Variant.FLSS), patch, terms);
        float[] expected = diffract.colour.ColourPath.SRGB.displayRgb(
                flss.xyz(new Direction(0, 0, 1), new Direction(0, 0, 1)).scaled(exposure));
        int p = 4 * (16 * 33 + 16);
        assertTrue(expected[1] > 0.1, "the specular centre must be lit");
        for (int k = 0; k < 3; k++) {
            assertEquals(expected[k], rgba[p + k], 2.0 / 255, "centre pixel channel " + k);
        }
    }

    /**
     * A render loop (a GL context current, a framebuffer of its own bound) that asks for a table it has not got:
     * the bake runs on a thread of its own and leaves the caller's context current with its bindings unchanged
     * (baking on the same thread let JOGL rebind the caller's framebuffer, and the viewer's frame came out black).
     */
    @Test
    void bakingFromInsideAGlContextLeavesThatContextAlone() {
        GlTestSupport.assumeOffscreenGl();
        TaylorTerms terms = RenderTestSupport.terms(RenderTestSupport.BLAZED);
        BrdfSettings settings = RenderTestSupport.settings(Variant.BAKED).with(b -> b.bakedSamples(9, 2)).with(b -> b.lambdaStepNm(20));
        BakedTables tables = new BakedTables();
        try (diffract.jrtr.OffscreenTarget outer = new diffract.jrtr.OffscreenTarget(new diffract.jrtr.Renderer(
                new diffract.jrtr.scenegraph.Group("empty"), new diffract.jrtr.scenegraph.Camera(),
                new diffract.jrtr.scenegraph.Frustum()))) {
            int[] bindings = outer.withContext(gl -> {
                int[] framebuffer = new int[1];
                gl.glGenFramebuffers(1, framebuffer, 0);
                gl.glBindFramebuffer(com.jogamp.opengl.GL.GL_FRAMEBUFFER, framebuffer[0]);
                Object context = diffract.jrtr.contexts.HeadlessGL.currentContext();
                assertNotNull(context, "a context is current inside withContext");
                tables.of(terms, settings, Reporter.SILENT);
                int[] after = new int[3];
                gl.glGetIntegerv(com.jogamp.opengl.GL2ES3.GL_DRAW_FRAMEBUFFER_BINDING, after, 0);
                after[1] = framebuffer[0];
                after[2] = context.equals(diffract.jrtr.contexts.HeadlessGL.currentContext()) ? 1 : 0;
                gl.glBindFramebuffer(com.jogamp.opengl.GL.GL_FRAMEBUFFER, 0);
                gl.glDeleteFramebuffers(1, framebuffer, 0);
                return after;
            });
            assertEquals(1, bindings[2], "the caller's context is still current");
            assertEquals(bindings[1], bindings[0], "the caller's framebuffer is still bound");
        }
        assertEquals(1, tables.bakeCount() + tables.loadCount());
    }

    private static Xyz spectralXyz(PatchSpectrum spectrum, WavelengthSampling sampling, double u, double v, double w) {
        WavelengthSampling.Quadrature q = sampling.quadratureFor(u, v);
        double[] power = new double[q.lambdasNm().length];
        for (int j = 0; j < power.length; j++) {
            power[j] = spectrum.power(u, v, w, q.lambdasNm()[j] * 1e-3);
        }
        return SpectralIntegrator.weightedSum(q.xyzWeights(), power);
    }
}
