package diffract.app;

import diffract.bench.BenchPatch;
import diffract.bench.BenchRunner;
import diffract.bench.MapError;
import diffract.bench.ReferenceMaps;
import diffract.bench.ReferenceSet;
import diffract.colour.DeltaEStatistics;
import diffract.colour.Srgb;
import diffract.jrtr.contexts.GLInfo;
import diffract.jrtr.OffscreenTarget;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.LightSource;
import diffract.optics.Methods;
import diffract.optics.settings.PixelFilter;
import diffract.optics.Variant;
import diffract.render.GpuBrdfMap;
import diffract.scene.Fabricator;
import diffract.scene.SceneSetup;
import diffract.util.DiskCache;
import diffract.util.ImageFiles;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * {@code diffract bench --gpu-suite}: the table a GPU machine fills in a few minutes. For every GPU variant with the
 * default scene's settings, and for the thesis' configuration (FLSS, N = 30, 5 nm, 65 um coherence length), it
 * renders
 * <ul>
 *   <li>the default scene (the snake with the Elaphe-like patch) at the suite size (1920 x 1080 on a GPU): GPU
 *       ms/frame from GL timer queries, and CIEDE2000 over the snake's pixels against the same scene and physics
 *       drawn with FLSS at 1 nm and {@link #REFERENCE_ORDER} terms (no CPU renderer of meshes exists; the maps
 *       below carry the error against the exact model);</li>
 *   <li>the BRDF map of the scene's patch at the suite height (1080 x 1080): ms/frame, and CIEDE2000 over the lit
 *       pixels of the maps at theta_i 0, 45 and 75 degrees against the CPU reference (exact model, 1 nm), at the
 *       error size (128 px: the CPU reference of a 1080 px map would take longer than the whole suite).</li>
 * </ul>
 * On a software rasteriser (llvmpipe) the suite size is 1/8 of that, 240 x 135, unless {@code --suite-size} says.
 * Writes {@code gpu-suite.csv}, {@code gpu-suite.md} and the scene pictures {@code scene-*.png} into the output
 * folder; the reference maps are kept in the disk cache ({@link DiskCache}).
 */
final class GpuSuite {
    /** The thesis' method: the suite's thesis row, and its converged maps under a point light (at 1 nm). */
    private static final Variant THESIS = Methods.Role.THESIS.method();
    /** The converged maps of the methods that filter the light. */
    private static final Variant FILTERING = Methods.Role.FILTERING.method();

    static final int FULL_WIDTH = 1920;
    static final int FULL_HEIGHT = 1080;
    /** Software rasterisers get the suite at 1/8 of the full size in each direction. */
    static final int SOFTWARE_DIVISOR = 8;
    /** Taylor terms of the scene reference: the remainder bound of the default patch is 2e-8 at N = 30. */
    static final int REFERENCE_ORDER = 30;
    static final List<String> COLUMNS = List.of("kind", "configuration", "variant", "terms", "lambda_step_nm",
            "window_radius", "coherence_length_um", "width", "height", "ms_per_frame", "error_size", "deltaE_mean",
            "deltaE_p95", "compared_pixels", "reference", "gl_vendor", "gl_renderer", "gl_version", "gl_platform");

    /** One measured row. */
    record Row(String kind, String configuration, BrdfSettings settings, int width, int height, double msPerFrame,
               int errorSize, double deltaEMean, double deltaEP95, int comparedPixels, String reference) {
    }

    private final Path outputDir;
    private final int[] requestedSize;
    private final int errorSizePx;
    private final int frames;
    private final Reporter reporter;
    private final List<Variant> variants;
    private final Path sceneFile;
    private final boolean scenesOnly;

    /**
     * @param requestedSize {width, height}, or null for the automatic size
     * @param errorSizePx   size of the BRDF maps compared with the CPU reference
     * @param frames        timed frames per row (median; at least 10), after 2 unmeasured ones
     * @param variants      the variants drawn with the scene's settings (the thesis' configuration always is)
     */
    GpuSuite(Path outputDir, int[] requestedSize, int errorSizePx, int frames, List<Variant> variants,
             Reporter reporter) {
        this(outputDir, requestedSize, errorSizePx, frames, variants, null, false, reporter);
    }

    /**
     * @param sceneFile  the scene drawn, null for the default scene
     * @param scenesOnly the scene rows of the variants only: no BRDF maps, no thesis row (a viewer's frame rate)
     */
    GpuSuite(Path outputDir, int[] requestedSize, int errorSizePx, int frames, List<Variant> variants, Path sceneFile,
             boolean scenesOnly, Reporter reporter) {
        this.sceneFile = sceneFile;
        this.scenesOnly = scenesOnly;
        for (Variant v : variants) {
            if (!v.runsOnGpu()) {
                throw new UserInputException("the " + v.spec() + " runs on the CPU only: the suite measures the GPU"
                        + " against it; list GPU variants");
            }
        }
        this.variants = List.copyOf(variants);
        if (frames < 10) {
            throw new UserInputException("--frames must be at least 10 for a median, got " + frames);
        }
        if (errorSizePx < 8 || errorSizePx > 1024) {
            throw new UserInputException("--error-size must be between 8 and 1024 pixels, got " + errorSizePx);
        }
        this.outputDir = outputDir;
        this.requestedSize = requestedSize;
        this.errorSizePx = errorSizePx;
        this.frames = frames;
        this.reporter = reporter;
    }

    /** The suite size: the one asked for, else full size, divided by {@link #SOFTWARE_DIVISOR} on software GL. */
    static int[] size(int[] requested, GLInfo gl) {
        if (requested != null) {
            return requested.clone();
        }
        return isSoftware(gl) ? new int[] {FULL_WIDTH / SOFTWARE_DIVISOR, FULL_HEIGHT / SOFTWARE_DIVISOR}
                : new int[] {FULL_WIDTH, FULL_HEIGHT};
    }

    /** Mesa's CPU rasterisers: their "GPU" times are CPU times of the shader code. */
    static boolean isSoftware(GLInfo gl) {
        String renderer = gl.renderer() == null ? "" : gl.renderer().toLowerCase(Locale.ROOT);
        return renderer.contains("llvmpipe") || renderer.contains("softpipe") || renderer.contains("swrast")
                || renderer.contains("software");
    }

    /** The configurations: the variants with the scene's settings, then the thesis' configuration. */
    static List<String[]> names(List<Variant> variants) {
        List<String[]> names = new ArrayList<>();
        for (Variant v : variants) {
            names.add(new String[] {"scene settings", v.label()});
        }
        names.add(new String[] {"thesis", THESIS.label()});
        return names;
    }

    /** Every variant the GPU draws. */
    static List<Variant> gpuVariants() {
        return Arrays.stream(Variant.values()).filter(Variant::runsOnGpu).toList();
    }

    /**
     * The same physics as {@code s}, converged: for a filtering variant the lobes method (exact in wavelength; within
     * CIEDE2000 1 of the filtered reference on BRDF maps, docs/measurements/bench/filtering.md), else FLSS at 1 nm; with at least
     * {@link #REFERENCE_ORDER} terms.
     */
    static BrdfSettings converged(BrdfSettings s) {
        int order = Math.max(REFERENCE_ORDER, s.taylor().highestOrder());
        return s.variant().filtersLight() ? s.with(b -> b.variant(FILTERING).highestOrder(order))
                : s.with(b -> b.variant(THESIS).lambdaStepNm(1).highestOrder(order));
    }

    private void writePng(String file, float[] rgb, int[] size) {
        try {
            ImageFiles.writePng(outputDir.resolve(file), rgb, size[0], size[1], 3);
        } catch (IOException e) {
            throw new UserInputException("cannot write " + outputDir.resolve(file) + ": " + e.getMessage(), e);
        }
    }

    /**
     * The row's settings. Every row draws a point light with point-sampled pixels, the physics every variant shares,
     * so that each is timed and compared on the same picture; the filtering methods under a light of finite size are
     * measured by {@code bench --filtering}.
     */
    private static BrdfSettings settingsOf(String[] name, BrdfSettings scene) {
        if (name[0].equals("thesis")) {
            return BrdfSettings.thesis(THESIS);
        }
        Variant v = Variant.parse(name[1]);
        return v.filtersLight() ? scene.with(b -> b.variant(v))
                : scene.with(b -> b.variant(v).lightSizeDeg(0).pixelFilter(PixelFilter.POINT));
    }


    /** Runs every row and writes the files; returns the rows. */
    List<Row> run() throws IOException {
        Files.createDirectories(outputDir);
        Path scene = sceneFile != null ? sceneFile : DemoCommand.defaultScene(outputDir);
        SceneSetup base = Fabricator.fabricate(scene, reporter);
        GLInfo gl;
        try (OffscreenTarget probe = sceneTarget(base)) {
            gl = probe.info();
        }
        int[] size = size(requestedSize, gl);
        reporter.info(String.format(Locale.ROOT, "gpu suite: %dx%d scene and %dx%d maps on %s%s", size[0], size[1],
                size[1], size[1], gl.renderer(), requestedSize == null && isSoftware(gl)
                        ? " (a software rasteriser: 1/" + SOFTWARE_DIVISOR + " of 1920x1080)" : ""));
        List<Row> rows = new ArrayList<>();
        // per physics (wavelength range, coherence, refractive index) one converged picture the rows compare with
        Map<String, float[]> sceneReferences = new HashMap<>();
        List<String[]> configurations = scenesOnly ? variants.stream().map(v -> new String[] {"scene settings",
                v.label()}).toList() : names(variants);
        for (String[] name : configurations) {
            BrdfSettings settings = settingsOf(name, base.settings());
            BrdfSettings converged = converged(settings);
            float[] reference = sceneReferences.computeIfAbsent(converged.toString(), k -> {
                try (OffscreenTarget target = sceneTarget(base.withSettings(converged))) {
                    float[] rgb = RenderCommand.frameRgb(target, size[0], size[1],
                            "pixels of the converged picture of " + fileName(name), reporter);
                    writePng("scene-reference-" + fileName(name) + ".png", rgb, size);
                    return rgb;
                }
            });
            float[] picture;
            double ms;
            try (OffscreenTarget target = sceneTarget(base.withSettings(settings))) {
                picture = RenderCommand.frameRgb(target, size[0], size[1], "pixels of the picture of " + fileName(name),
                        reporter);
                ms = target.measureMedianMs(size[0], size[1], 2, frames);
            }
            writePng("scene-" + fileName(name) + ".png", picture, size);
            boolean[] covered = covered(reference);
            DeltaEStatistics error = DeltaEStatistics.of(Srgb.xyzOfDisplayRgb(reference), Srgb.xyzOfDisplayRgb(picture),
                    covered);
            rows.add(log(new Row("scene", name[0], settings, size[0], size[1], ms, size[0], error.mean(), error.p95(),
                    error.pixels(), "gpu " + converged.variant().spec() + " N=" + converged.taylor().highestOrder()
                    + (converged.variant().filtersLight() ? "" : " 1 nm"))));
        }
        if (base.stage().staged() && base.stage().glossyAlpha() == null && !rows.isEmpty()) {
            rows.add(log(glossyRow(base, rows.get(0).settings(), size)));
        }
        if (scenesOnly) {
            return written(rows, gl);
        }
        BenchPatch patch = new BenchPatch("scene-patch", base.patch(), base.light().phiDeg());
        ReferenceMaps references = new ReferenceMaps(DiskCache.user(), reporter);
        int mapSize = size[1];
        BrdfSettings mapBase = mapSettings(base.settings());
        boolean mapsUnderTheSun = mapBase != base.settings();
        if (mapsUnderTheSun) {
            double sceneDeg = base.settings().illumination().light().angularDiameterDeg();
            reporter.info("gpu suite: the BRDF maps under the sun's " + number(LightSource.SUN_DEG) + "-degree disc, "
                    + "not the scene's " + number(sceneDeg) + "-degree light: the CPU reference of a map under a "
                    + "disc that wide takes hours");
        }
        for (String[] name : names(variants)) {
            BrdfSettings settings = settingsOf(name, mapBase);
            ReferenceSet against = ReferenceSet.of(references, patch, BenchRunner.LIGHTS_DEG, errorSizePx, settings);
            BrdfSettings shown = against.drawnFor(settings);
            List<float[]> maps;
            double ms;
            try (GpuBrdfMap map = base.pipeline().gpuMap(shown, shown.spectral().lambdaMinNm(), reporter)) {
                maps = against.drawnBy(map);
                ms = map.medianMsPerFrame(Direction.fromSphericalDeg(BenchRunner.TIMED_LIGHT_DEG, patch.phiIDeg()),
                        mapSize, 2, frames);
            }
            MapError error = against.error(maps);
            rows.add(log(new Row("brdf map", name[0], settings, mapSize, mapSize, ms, errorSizePx, error.mean(),
                    error.p95(), error.litPixels(), settings.variant().filtersLight() && mapsUnderTheSun
                    ? "cpu exact 1 nm under the sun's disc" : "cpu exact 1 nm")));
        }
        return written(rows, gl);
    }

    /**
     * The settings the BRDF map rows draw: the scene's, under the sun's disc where the scene's light is wider (a staged
     * scene's soft key light). The CPU reference integrates a disc by the point reference over its directions
     * ({@code DiscLightAverage}): a disc many pixels wide takes its finest rule at every pixel, 32 x 96 point
     * references, where the sun takes a few (docs/guide/headless-gl.md, "The GPU suite").
     */
    static BrdfSettings mapSettings(BrdfSettings scene) {
        return scene.illumination().light().angularDiameterDeg() > LightSource.SUN_DEG
                ? scene.with(b -> b.lightSizeDeg(LightSource.SUN_DEG)) : scene;
    }

    /** The GGX roughness of the glossy material the staged scene's cost is compared with. */
    static final double GLOSSY_ALPHA = 0.2;
    static final String GLOSSY_CONFIGURATION = "glossy in place";

    /**
     * The staged scene with its scales a glossy dielectric (GGX, {@link #GLOSSY_ALPHA}) in place of the diffraction
     * BRDF of {@code settings}, timed like the other rows: the cost of the diffraction beside a standard material,
     * all else (lights, ground, shadow, pigment, tone mapping) the same. It is compared with nothing.
     */
    private Row glossyRow(SceneSetup base, BrdfSettings settings, int[] size) {
        SceneSetup glossy = base.withSettings(settings).withStage(base.stage().withGlossyScales(GLOSSY_ALPHA));
        float[] picture;
        double ms;
        try (OffscreenTarget target = sceneTarget(glossy)) {
            picture = target.renderRgb(size[0], size[1]);
            ms = target.measureMedianMs(size[0], size[1], 2, frames);
        }
        writePng("scene-glossy.png", picture, size);
        return new Row("scene", GLOSSY_CONFIGURATION, settings, size[0], size[1], ms, size[0], Double.NaN, Double.NaN,
                0, "none (GGX alpha " + GLOSSY_ALPHA + " in place of the diffraction: its cost)");
    }

    /** Writes gpu-suite.csv and gpu-suite.md of the rows; returns them. */
    private List<Row> written(List<Row> rows, GLInfo gl) throws IOException {
        Files.writeString(outputDir.resolve("gpu-suite.csv"), csv(rows, gl), StandardCharsets.UTF_8);
        Files.writeString(outputDir.resolve("gpu-suite.md"), markdown(rows, gl), StandardCharsets.UTF_8);
        return rows;
    }

    private Row log(Row r) {
        reporter.info(String.format(Locale.ROOT, "gpu suite: %-8s %-14s %-6s %dx%d: %9.2f ms/frame, CIEDE2000 mean %.3f "
                        + "p95 %.3f (%d px at %d, against %s)", r.kind(), r.configuration(), r.settings().variant().label(),
                r.width(), r.height(), r.msPerFrame(), r.deltaEMean(), r.deltaEP95(), r.comparedPixels(), r.errorSize(),
                r.reference()));
        return r;
    }

    private OffscreenTarget sceneTarget(SceneSetup setup) {
        ViewerModel model = ViewerModel.load(setup, reporter);
        model.bakeIfNeeded(reporter);
        return new OffscreenTarget(new ViewerRenderer(model));
    }

    private static String fileName(String[] name) {
        return name[0].equals("thesis") ? "thesis" : name[1];
    }

    /** The pixels that show the scene's object rather than the background (in the reference picture). */
    static boolean[] covered(float[] rgb) {
        float[] clear = ViewerRenderer.CLEAR_COLOUR;
        boolean[] covered = new boolean[rgb.length / 3];
        for (int p = 0; p < covered.length; p++) {
            covered[p] = Math.abs(rgb[3 * p] - clear[0]) > 1e-3 || Math.abs(rgb[3 * p + 1] - clear[1]) > 1e-3
                    || Math.abs(rgb[3 * p + 2] - clear[2]) > 1e-3;
        }
        return covered;
    }

    static String csv(List<Row> rows, GLInfo gl) {
        StringBuilder b = new StringBuilder(String.join(",", COLUMNS)).append('\n');
        for (Row r : rows) {
            BrdfSettings s = r.settings();
            b.append(String.join(",", r.kind(), r.configuration(), s.variant().label(),
                    Integer.toString(s.taylor().highestOrder()), number(s.spectral().lambdaStepNm()),
                    Integer.toString(s.window().radius()), number(4 * s.illumination().sigmaSpatialUm()), Integer.toString(r.width()), Integer.toString(r.height()),
                    number(r.msPerFrame()), Integer.toString(r.errorSize()), number(r.deltaEMean()),
                    number(r.deltaEP95()), Integer.toString(r.comparedPixels()), field(r.reference()), field(gl.vendor()),
                    field(gl.renderer()), field(gl.version()), field(gl.platform()))).append('\n');
        }
        return b.toString();
    }

    static String markdown(List<Row> rows, GLInfo gl) {
        StringBuilder b = new StringBuilder("GPU suite on " + gl + "\n\n");
        b.append("| what | configuration | variant | N | step nm | size | ms/frame | CIEDE2000 mean | p95 | against |\n");
        b.append("|---|---|---|---|---|---|---|---|---|---|\n");
        for (Row r : rows) {
            BrdfSettings s = r.settings();
            boolean compared = !Double.isNaN(r.deltaEMean());
            b.append(String.format(Locale.ROOT, "| %s | %s | %s | %d | %s | %dx%d | %.2f | %s | %s | %s |%n",
                    r.kind(), r.configuration(), s.variant().label(), s.taylor().highestOrder(),
                    number(s.spectral().lambdaStepNm()), r.width(), r.height(), r.msPerFrame(),
                    compared ? String.format(Locale.ROOT, "%.3f", r.deltaEMean()) : "-",
                    compared ? String.format(Locale.ROOT, "%.3f", r.deltaEP95()) : "-",
                    compared ? r.reference() + " at " + r.errorSize() + " px" : r.reference()));
        }
        glossyRatio(rows).ifPresent(ratio -> b.append(String.format(Locale.ROOT, "%nThe staged scene with the "
                + "diffraction BRDF takes %.2f times the time of the same scene with a glossy GGX material.%n", ratio)));
        return b.toString();
    }

    /** The first scene row's time over the glossy row's, when both were run. */
    static java.util.Optional<Double> glossyRatio(List<Row> rows) {
        java.util.Optional<Row> glossy = rows.stream().filter(r -> r.configuration().equals(GLOSSY_CONFIGURATION))
                .findFirst();
        java.util.Optional<Row> first = rows.stream().filter(r -> r.kind().equals("scene")
                && !r.configuration().equals(GLOSSY_CONFIGURATION)).findFirst();
        return glossy.isPresent() && first.isPresent()
                ? java.util.Optional.of(first.get().msPerFrame() / glossy.get().msPerFrame())
                : java.util.Optional.empty();
    }

    private static String number(double v) {
        if (Double.isNaN(v)) {
            return "nan";
        }
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v)
                : String.format(Locale.ROOT, "%.6g", v).replaceAll("(\\.\\d*?)0+$", "$1").replaceAll("\\.$", "");
    }

    /** Driver strings with their commas as semicolons, so that every row splits on commas. */
    private static String field(String text) {
        return text == null ? "" : text.replace(',', ';');
    }
}
