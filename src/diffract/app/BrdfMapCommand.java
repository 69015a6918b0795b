package diffract.app;

import diffract.app.jobs.PieceFolder;
import diffract.app.jobs.PieceManifest;
import diffract.app.jobs.SplitCommand;
import diffract.app.jobs.TileOptions;
import diffract.app.options.BrdfOptions;
import diffract.app.options.CacheOption;
import diffract.app.options.GpuOption;
import diffract.app.options.OptionNames;
import diffract.app.options.OptionTypes;
import diffract.app.options.PatchOptions;
import diffract.app.options.QuietOption;
import diffract.bench.AutoCalibration;
import diffract.bench.AutoChoice;
import diffract.bench.AutoVariant;
import diffract.colour.ColourPath;
import diffract.colour.Srgb;
import diffract.colour.Xyz;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.LightPolicy;
import diffract.optics.MapBand;
import diffract.optics.Methods;
import diffract.optics.Variant;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.LightSource;
import diffract.optics.io.SamplingCheck;
import diffract.optics.maps.AutoExposure;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.Quantity;
import diffract.optics.validity.ScalarValidity;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.pipeline.DiffractionPipeline;
import diffract.pipeline.NamedPatch;
import diffract.precompute.TermFolders;
import diffract.precompute.ThesisFormat;
import diffract.render.DiffractionShaders;
import diffract.render.GpuBrdfMap;
import diffract.render.ShortPixels;
import diffract.scene.LightDirection;
import diffract.util.ImageFiles;
import diffract.util.OpenExr;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;

/** {@code diffract brdfmap}: the BRDF of a patch for one light direction, over all viewing directions. */
@Command(name = "brdfmap", mixinStandardHelpOptions = true, abbreviateSynopsis = true)
final class BrdfMapCommand implements SplitCommand, Callable<Integer> {
    /** Where a map is computed. */
    enum Engine { CPU, GPU }

    @Mixin GpuOption gpu;
    @Mixin PatchOptions patch;
    @Mixin BrdfOptions brdf;
    @Mixin QuietOption quiet;
    @Mixin CacheOption cache;
    @Mixin TileOptions tiles;
    @Spec CommandSpec spec;

    @Option(names = "--theta-i", defaultValue = "30", paramLabel = "DEG") double thetaIDeg;

    @Option(names = {"-o", "--output"}, paramLabel = "MAP.png|MAP.exr") Path output;

    @ArgGroup(exclusive = false, validate = false, heading = "Light:%n")
    Light light = new Light();

    @ArgGroup(exclusive = false, validate = false, heading = "Terms and engine:%n")
    Engines engines = new Engines();

    @ArgGroup(exclusive = false, validate = false, heading = "Picture:%n")
    Picture picture = new Picture();

    /** Where the light comes from and what it holds. */
    static final class Light {
        @Option(names = "--phi-i", paramLabel = "DEG") Double phiIDeg;

        @Option(names = "--lambda", paramLabel = "NM") Double lambdaNm;
    }

    /** Where the terms come from and where the map is computed. */
    static final class Engines {
        @Option(names = "--terms-dir", paramLabel = "DIR") Path termsDir;

        @Option(names = "--terms-height-unit", defaultValue = "auto", paramLabel = "UNIT",
                converter = OptionTypes.HeightUnitConverter.class)
        ThesisFormat.HeightUnit termsHeightUnit = ThesisFormat.HeightUnit.AUTO;

        @Option(names = "--engine", paramLabel = "E") Engine engine;

        @Option(names = "--time") boolean time;
    }

    /** The map's size and how it is shown. */
    static final class Picture {
        @Option(names = "--size", defaultValue = "256", paramLabel = "S", converter = OptionTypes.ImageSize.Side.class)
        int size = 256;

        @Option(names = "--exposure", defaultValue = "1", paramLabel = "E|auto",
                converter = OptionTypes.Exposure.Converter.class)
        OptionTypes.Exposure exposure = new OptionTypes.Exposure(1.0);

        @Option(names = "--colour", defaultValue = "srgb", paramLabel = "PATH") ColourPath colour = ColourPath.SRGB;

        @Option(names = "--pfm", paramLabel = "MAP.pfm") Path pfm;

        @Option(names = "--exr", paramLabel = "MAP.exr") Path exr;

        @Option(names = "--exr-half") boolean exrHalf;
    }

    @Override
    public Integer call() throws IOException {
        Engine where = validate();
        if (tiles.tile == null) {
            requireOutputs();
        }
        Reporter reporter = quiet.reporter();
        long start = System.nanoTime();
        NamedPatch named = patch.load("", reporter);
        HeightField field = named.meanSubtracted();
        double phi = light.phiIDeg != null ? light.phiIDeg : patch.periodAzimuthDeg("");
        BrdfSettings asked = settings(field, phi, reporter);
        // a map shown at a known exposure is drawn for it (the lobes method's cutoff, LobeQuadrature.shownAt)
        BrdfSettings settings = picture.exposure.automatic() ? asked : asked.shownAt(picture.exposure.factor());
        MemoryCheck.brdfMap(field, settings, picture.size, thetaIDeg, light.lambdaNm);
        double shortestLambdaNm = light.lambdaNm != null ? Math.min(light.lambdaNm, settings.spectral().lambdaMinNm())
                : settings.spectral().lambdaMinNm();
        SamplingCheck.warnAboutAliasing(field, light.lambdaNm != null ? light.lambdaNm : settings.spectral().lambdaMinNm(),
                light.lambdaNm != null ? light.lambdaNm : settings.spectral().lambdaMaxNm(), thetaIDeg, reporter);
        DiffractionPipeline pipeline = engines.termsDir != null
                ? DiffractionPipeline.withTerms(named,
                        TermFolders.read(engines.termsDir, engines.termsHeightUnit, reporter), engines.termsDir.toString())
                : DiffractionPipeline.cached(named, settings.spectral().lambdaMinNm());
        CoherenceWindow window = settings.coherenceWindow();
        reporter.info(String.format(Locale.ROOT, "%s, %dx%d patch of %.3f x %.3f um, sigma_f = %.3f x %.3f texels",
                settings.variant().spec(), field.cols(), field.rows(), field.widthUm(), field.heightExtentUm(),
                window.sigmaTexels(field.widthUm()), window.sigmaTexels(field.heightExtentUm())));
        Direction wi = Direction.fromSphericalDeg(thetaIDeg, phi);
        if (!settings.variant().solvesMaxwell()) {
            warnWhereTheScalarModelFails(field, settings, reporter);
        }
        if (tiles.tile != null) {
            writePiece(pipeline, settings, named, phi, shortestLambdaNm, start, reporter);
            return 0;
        }
        float[] map = map(where, pipeline, settings, wi, shortestLambdaNm, reporter);
        if (picture.exposure.automatic()) {
            // the exposure is the map's own: where it shows the map brighter than the cutoff assumed, draw it again
            // for that exposure (the map can only gain light, so the exposure found first is never too low)
            BrdfSettings shown = settings.shownAt(AutoExposure.of(luminance(map), picture.size, -wi.x(), -wi.y()));
            // only a method that reads the cutoff draws a different map at another exposure
            if (shown != settings && settings.variant().readsCutoff()) {
                reporter.info(String.format(Locale.ROOT, "drawn again for its exposure: the lobes' cutoff %.3g of "
                        + "white", shown.lobes().cutoff()));
                settings = shown;
                map = map(where, pipeline, settings, wi, shortestLambdaNm, reporter);
            }
        }
        write(map, wi, settings, field.widthUm(), field.heightExtentUm(), reporter);
        System.out.printf(Locale.ROOT, "wrote %s (%dx%d, %s%s%s) in %.1f s%n", output, picture.size, picture.size,
                settings.variant().spec(), where == Engine.GPU ? ", gpu" : "",
                light.lambdaNm != null ? ", " + light.lambdaNm + " nm" : "", (System.nanoTime() - start) * 1e-9);
        return 0;
    }

    /**
     * The outputs named can be written (checked before any work): -o, --pfm and --exr, and --exr-half only with an
     * OpenEXR one. Merge checks the outputs it was given the same way.
     */
    void requireOutputs() {
        if (output == null) {
            throw new UserInputException("brdfmap needs -o MAP.png (or MAP.exr), the map to write; with --tile I/N "
                    + "--pieces DIR it writes one piece of it instead");
        }
        OutputPaths.require(OutputPaths.file("-o", output, "map.png", PNG, EXR),
                OutputPaths.file("--pfm", picture.pfm, "map.pfm", ".pfm"),
                OutputPaths.file("--exr", picture.exr, "map.exr", EXR));
        if (picture.exrHalf && picture.exr == null && !outputIsExr()) {
            throw new UserInputException("--exr-half goes with an OpenEXR output: --exr MAP.exr or -o MAP.exr");
        }
    }

    /** With --tile: the piece's rows, written with their manifest into --pieces DIR. */
    private void writePiece(DiffractionPipeline pipeline, BrdfSettings settings, NamedPatch patch, double phiDeg, double shortestLambdaNm, long startNanos, Reporter reporter)
            throws IOException {
        TileOptions.Tile tile = tiles.tile;
        MapBand band = MapBand.of(tile.index(), tile.count(), picture.size);
        Direction wi = Direction.fromSphericalDeg(thetaIDeg, phiDeg);
        var cpu = pipeline.cpuBrdf(settings, shortestLambdaNm, reporter);
        long work = System.nanoTime();
        float[] floats = light.lambdaNm != null
                ? BrdfMap.monochromatic(cpu, wi, light.lambdaNm, picture.size, band, reporter)
                : BrdfMap.xyz(cpu, wi, picture.size, band, reporter);
        long done = System.nanoTime();
        int channels = light.lambdaNm != null ? 1 : 3;
        HeightField field = patch.meanSubtracted();
        PieceManifest manifest = new PieceManifest(PieceManifest.FORMAT, spec.name(), tile.index(), tile.count(),
                band.fromRow(), band.toRow(), picture.size, picture.size * channels, field.contentSha256(),
                floatSettings(settings, patch, phiDeg), pictureSettings(), TileOptions.argumentsWithoutTile(spec), null,
                null, null);
        PieceFolder.write(tiles.pieces, manifest, floats);
        // submit reads this line: the piece's fixed cost (loading, terms) against its work (the pixels)
        System.out.printf(Locale.ROOT, "wrote piece %s (rows %s of %d) into %s: setup %.2f s, work %.2f s%n", tile,
                band, picture.size, tiles.pieces, (work - startNanos) * 1e-9, (done - work) * 1e-9);
    }

    /** Everything besides the patch and the map size that changes a piece's floats, as merge compares it. */
    private Map<String, String> floatSettings(BrdfSettings settings, NamedPatch patch, double phiDeg) {
        Map<String, String> s = new LinkedHashMap<>();
        s.put("version", diffract.util.Version.VERSION);
        s.put("brdf", settings.toString());
        s.put("thetaIDeg", Double.toString(thetaIDeg));
        s.put("phiIDeg", Double.toString(phiDeg));
        s.put("patchWidthUm", Double.toString(patch.meanSubtracted().widthUm()));
        s.put("patchHeightUm", Double.toString(patch.meanSubtracted().heightExtentUm()));
        s.put("lambdaNm", String.valueOf(light.lambdaNm));
        s.put("patchMaxHeightUm", String.valueOf(patch.maxHeightUm()));
        s.put("termsDir", engines.termsDir == null ? "cache" : engines.termsDir.toAbsolutePath().normalize()
                + " (" + engines.termsHeightUnit + ")");
        return s;
    }

    /** What changes the pictures written from the floats, not the floats. */
    private Map<String, String> pictureSettings() {
        Map<String, String> s = new LinkedHashMap<>();
        s.put("exposure", picture.exposure.automatic() ? "auto" : Double.toString(picture.exposure.factor()));
        s.put("colour", picture.colour.name());
        s.put("exrHalf", Boolean.toString(picture.exrHalf));
        return s;
    }

    /**
     * Merge's half of a split run: the S x S floats that the pieces assembled, written as this command would have
     * written them had it computed them whole (the same exposure, notices and files, bit for bit).
     */
    void writeMerged(float[] map, double phiDeg, double patchWidthUm, double patchHeightUm, Reporter reporter)
            throws IOException {
        requireOutputs();
        write(map, Direction.fromSphericalDeg(thetaIDeg, phiDeg), brdf.apply(base(requested())), patchWidthUm,
                patchHeightUm, reporter);
    }

    /**
     * A point light is well defined at any angle above the horizon: the map's light goes up to 90 degrees,
     * exclusive (the gain factor vanishes there), unlike the viewer's and scenes' lights, which stop at
     * {@link LightDirection#MAX_THETA_DEG} so that their discs and shadows stay above it.
     */
    static final double HORIZON_DEG = 90;

    private static String num(double v) {
        return new java.math.BigDecimal(v).round(new java.math.MathContext(6)).stripTrailingZeros().toPlainString();
    }

    private static final String PNG = ".png";
    private static final String EXR = ".exr";

    private boolean outputIsExr() {
        return output.getFileName() != null
                && output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(EXR);
    }

    /** Everything that needs no file: bad usage fails before minutes of work. Returns where the map is computed. */
    private Engine validate() {
        patch.validateRequired();
        brdf.validate();
        if (!(thetaIDeg >= 0 && thetaIDeg < HORIZON_DEG)) {
            throw new UserInputException("--theta-i must be in [0, 90) degrees (a point light up to the horizon,"
                    + " which it never reaches), got " + thetaIDeg);
        }
        if (light.lambdaNm != null && !(light.lambdaNm > 0)) {
            throw new UserInputException("--lambda must be > 0 nm, got " + light.lambdaNm);
        }
        if (brdf.auto() && light.lambdaNm != null) {
            throw new UserInputException("--variant auto is calibrated on colour maps; leave out --lambda");
        }
        Engine where = engines.engine != null ? engines.engine : brdf.auto() ? Engine.GPU : Engine.CPU;
        Variant named = requested();
        if (where == Engine.GPU && !named.runsOnGpu()) {
            throw new UserInputException(DiffractionShaders.cpuOnly(named) + " (--engine cpu)");
        }
        if (where == Engine.CPU && !named.runsOnCpu()) {
            throw new UserInputException("the " + named.label() + " variant runs on the GPU only (--engine gpu); the "
                    + "CPU evaluates " + Methods.listed(Variant::runsOnCpu, "and"));
        }
        if (named.drawsTable() && light.lambdaNm != null) {
            throw new UserInputException(GpuBrdfMap.BAKED_HAS_NO_MONOCHROMATIC + " (--lambda)");
        }
        if (engines.time && where != Engine.GPU) {
            throw new UserInputException("--time measures the GPU: add --engine gpu");
        }
        validateTile(where);
        BrdfSettings settings = brdf.apply(base(named)); // a refused value fails now too
        if (settings.window().placement() == WindowPlacement.LOCAL) {
            throw new UserInputException(OptionNames.of(Quantity.WINDOW_PLACEMENT) + ": "
                    + DiffractionBrdf.LOCAL_NEEDS_A_SURFACE);
        }
        LightSource lightSource = settings.illumination().light();
        double rimDeg = thetaIDeg + lightSource.angularDiameterDeg() / 2;
        if (!lightSource.isPoint() && !(rimDeg < HORIZON_DEG)) {
            throw new UserInputException(String.format(Locale.ROOT, "--theta-i %s with --light-size-deg %s puts part"
                    + " of the light's disc below the horizon (theta_i + D/2 = %s degrees); a disc stays above it"
                    + " up to --theta-i below %s, a point light (--light-size-deg 0) up to 90", num(thetaIDeg),
                    num(lightSource.angularDiameterDeg()), num(rimDeg),
                    num(HORIZON_DEG - lightSource.angularDiameterDeg() / 2)));
        }
        if (!lightSource.isPoint() && light.lambdaNm != null) {
            throw new UserInputException("--lambda maps sample the light at its centre: drop --light-size-deg");
        }
        LightPolicy light = LightPolicy.of(settings);
        if (!brdf.auto() && !light.accepted()) {
            throw new UserInputException(OptionNames.of(light.quantity()) + ": " + light.reason().orElseThrow()
                    + " (--variant lobes)");
        }
        return where;
    }

    @Override
    public TileOptions tiles() {
        return tiles;
    }

    /**
     * The bands farthest from the map's middle row first, alternating top and bottom. Their pixels lie nearest the
     * horizon's rim, which the CPU's filtered pixels refine where their boxes cross it, and their directions are the
     * most grazing: an outer band of a 256 x 256 reference map in 8 pieces works 1.6 to 1.9 times as long as a middle
     * one (docs/measurements/pieces.md). Taken first, they leave the cheap middle bands to even out the workers' ends, and each
     * worker's start is paid beside its longest piece.
     */
    @Override
    public int[] dispatchOrder(int pieceCount) {
        double middle = (pieceCount - 1) / 2.0;
        return java.util.stream.IntStream.range(0, pieceCount).boxed()
                .sorted(java.util.Comparator.comparingDouble((Integer i) -> -Math.abs(i - middle))
                        .thenComparingInt(i -> i))
                .mapToInt(Integer::intValue).toArray();
    }

    @Override
    public Result result() {
        Map<String, Path> outputs = new LinkedHashMap<>();
        outputs.put("-o", output);
        if (picture.pfm != null) {
            outputs.put("--pfm", picture.pfm);
        }
        if (picture.exr != null) {
            outputs.put("--exr", picture.exr);
        }
        return new Result(picture.size, "rows", outputs, quiet.quiet);
    }

    /**
     * What {@code submit} checks before it starts any worker: the options as one run would (its outputs included),
     * and those that splitting adds (on the CPU, at most a band per row).
     */
    @Override
    public void validateSplit(int pieceCount) {
        Engine where = validate();
        if (where == Engine.GPU || brdf.auto()) {
            throw new UserInputException("submit splits the CPU's work (a GPU map takes seconds): run brdfmap alone, "
                    + "or drop --engine gpu and --variant auto");
        }
        if (pieceCount > picture.size) {
            throw new UserInputException("--piece-count " + pieceCount + ": a map of --size " + picture.size + " has only "
                    + picture.size + " rows to split");
        }
        requireOutputs();
    }

    /** --tile and --pieces go together, on the CPU, without the outputs that only merge writes. */
    private void validateTile(Engine where) {
        if (!tiles.requested("which band of rows to compute")) {
            return;
        }
        if (output != null || picture.pfm != null || picture.exr != null) {
            throw new UserInputException("--tile writes one piece into --pieces " + tiles.pieces + "; the map's "
                    + "-o, --pfm and --exr are written by 'diffract merge " + tiles.pieces + " -o MAP.png': drop them");
        }
        if (where == Engine.GPU || brdf.auto()) {
            throw new UserInputException("--tile splits the CPU's work (a GPU map takes seconds): drop --tile, or "
                    + "--engine gpu and --variant auto");
        }
        tiles.requireSplittable(picture.size, "a map of --size " + picture.size + " has only " + picture.size
                + " rows");
    }

    /**
     * The command's defaults for a variant: the thesis' configuration seen as the definitions say (a point light, the
     * canonical BRDF; each pixel the average over its square, honoured by lobes and the reference).
     */
    static BrdfSettings base(Variant variant) {
        return BrdfSettings.thesis(variant).with(b -> b.pixelFilter(PixelFilter.BOX));
    }

    /**
     * The variant asked for: the exact one by default; with auto, the thesis' method stands in until the calibration
     * chose.
     */
    Variant requested() {
        return brdf.auto() ? Methods.Role.THESIS.method() : brdf.variantOr(Methods.Role.EXACT.method());
    }

    /** The thesis' settings with the options given; with auto, the configuration its calibration chose. */
    private BrdfSettings settings(HeightField field, double phiDeg, Reporter reporter) {
        BrdfSettings settings = brdf.apply(base(requested()));
        if (!brdf.auto()) {
            return settings;
        }
        // the calibration computes reference maps of this patch
        MemoryCheck.brdfMap(field, settings.with(b -> b.variant(Methods.Role.EXACT.method())), AutoCalibration.SIZE_PX,
                0, null);
        AutoChoice choice = AutoVariant.choose(field, phiDeg, settings, brdf.maxDeltaE, reporter);
        System.out.println(choice.explanation());
        return AutoVariant.settings(choice, settings.taylor().expansion());
    }

    /** The map drawn where asked. */
    private float[] map(Engine where, DiffractionPipeline pipeline, BrdfSettings settings, Direction wi,
                        double shortestLambdaNm, Reporter reporter) {
        return where == Engine.GPU ? gpuMap(pipeline, settings, wi, shortestLambdaNm, reporter)
                : cpuMap(pipeline, settings, wi, shortestLambdaNm, reporter);
    }

    private float[] gpuMap(DiffractionPipeline pipeline, BrdfSettings settings, Direction wi, double shortestLambdaNm,
                           Reporter reporter) {
        try (GpuBrdfMap map = pipeline.gpuMap(settings, shortestLambdaNm, reporter)) {
            reporter.info("GPU: " + map.info().renderer() + ", " + map.info().version());
            // the bake's own note says what it baked and how long it took
            float[] values = light.lambdaNm != null ? map.monochromatic(wi, light.lambdaNm, picture.size)
                    : map.xyz(wi, picture.size);
            if (map.truncatedPixels() > 0) {
                reporter.warn(ShortPixels.warning(map.truncatedPixels(), (long) picture.size * picture.size,
                        "pixels of the map", map.info().renderer(), "draw the map with --engine cpu, at a larger "
                        + "--size (smaller pixels reach fewer lobes), or with --variant baked"));
            }
            if (engines.time) {
                double ms = light.lambdaNm != null ? map.medianMsPerFrameMonochromatic(wi, light.lambdaNm, picture.size, 2, 10)
                        : map.medianMsPerFrame(wi, picture.size, 2, 10);
                System.out.printf(Locale.ROOT, "gpu %.1f ms/frame (%s, %dx%d, median of 10, %s, %s)%n", ms,
                        settings.variant().spec(), picture.size, picture.size, settings.gpu().termFormat().label(),
                        map.info().renderer());
            }
            return values;
        }
    }

    private float[] cpuMap(DiffractionPipeline pipeline, BrdfSettings settings, Direction wi, double shortestLambdaNm,
                           Reporter reporter) {
        var cpu = pipeline.cpuBrdf(settings, shortestLambdaNm, reporter);
        return light.lambdaNm != null ? BrdfMap.monochromatic(cpu, wi, light.lambdaNm, picture.size, reporter)
                : BrdfMap.xyz(cpu, wi, picture.size, reporter);
    }

    /** rho of a monochromatic map, or Y of a colour one, per pixel. */
    private float[] luminance(float[] map) {
        int channels = light.lambdaNm != null ? 1 : 3;
        float[] luminance = new float[picture.size * picture.size];
        for (int p = 0; p < luminance.length; p++) {
            luminance[p] = map[channels * p + channels / 2];
        }
        return luminance;
    }

    /**
     * The PNG (display-encoded at the exposure) or OpenEXR (linear) of a colour or monochromatic map, and the optional
     * PFM and OpenEXR (linear, never exposed).
     */
    private void write(float[] map, Direction wi, BrdfSettings settings, double patchWidthUm, double patchHeightUm,
                       Reporter reporter)
            throws IOException {
        int channels = light.lambdaNm != null ? 1 : 3;
        float[] luminance = luminance(map);
        double e = picture.exposure.automatic() ? AutoExposure.of(luminance, picture.size, -wi.x(), -wi.y())
                : picture.exposure.factor();
        if (picture.exposure.automatic()) {
            reporter.info(String.format(Locale.ROOT, "auto exposure %.4g", e));
        }
        warnIfDark(luminance, wi, e, settings, patchWidthUm, patchHeightUm, reporter);
        float[] display = new float[map.length];
        float[] linear = new float[map.length];
        for (int p = 0; p < map.length; p += channels) {
            if (channels == 1) {
                display[p] = (float) Srgb.encode(map[p] * e);
                linear[p] = map[p];
                continue;
            }
            Xyz c = new Xyz(map[p], map[p + 1], map[p + 2]);
            System.arraycopy(picture.colour.displayRgb(c.scaled(e)), 0, display, p, 3);
            double[] lin = Srgb.linearFromXyz(c);
            for (int k = 0; k < 3; k++) {
                linear[p + k] = (float) lin[k];
            }
        }
        OpenExr.Precision precision = picture.exrHalf ? OpenExr.Precision.HALF : OpenExr.Precision.FLOAT;
        String comment = light.lambdaNm != null
                ? String.format(Locale.ROOT, "diffract BRDF map: the relative BRDF at %s nm", light.lambdaNm)
                : "diffract BRDF map: linear sRGB, unclipped, not exposed";
        if (outputIsExr()) {
            OpenExr.write(output, linear, picture.size, picture.size, channels, precision, comment);
        } else {
            ImageFiles.writePng(output, display, picture.size, picture.size, channels);
        }
        if (picture.pfm != null) {
            ImageFiles.writePfm(picture.pfm, linear, picture.size, picture.size, channels);
        }
        if (picture.exr != null) {
            OpenExr.write(picture.exr, linear, picture.size, picture.size, channels, precision, comment);
        }
    }

    /**
     * Where the patch lies outside the region where the scalar model is within a visible difference of Maxwell's
     * equations, one line says how far (docs/measurements/validity.md) and the command that draws it rigorously: this map with
     * --variant rigorous for a 1-D patch, its ridges' cross-section for a 2-D one.
     */
    /**
     * One line where the scalar model is expected visibly off Maxwell's equations on this patch (docs/measurements/validity.md): the
     * expected error, the rigorous command that would tell and, for the lobes method, the orders that close it. None
     * where the lobes already take their orders from Maxwell's equations.
     */
    private void warnWhereTheScalarModelFails(HeightField field, BrdfSettings settings, Reporter reporter) {
        if (settings.rigorous().orders() == diffract.optics.settings.OrderWeights.RIGOROUS) {
            return;
        }
        ScalarValidity.Estimate e = ScalarValidity.shipped().estimate(field, thetaIDeg,
                settings.illumination().gain());
        if (!e.visible()) {
            return;
        }
        String how = diffract.optics.validity.OrderComparison.refusal(field).isEmpty()
                ? "diffract brdfmap --variant rigorous " + patch.describe() + " --theta-i " + number(thetaIDeg)
                        + " draws it from Maxwell's equations, diffract orders lists its orders"
                : "the rigorous method solves 1-D patches, such as a snake patch's ridges alone, and 2-D cells of about a "
                        + "micrometre: diffract orders "
                        + "--synthetic elaphe-ridge --theta-i " + number(thetaIDeg);
        String fix = settings.variant().takesRigorousOrders() ? "; --orders rigorous takes the lobes' orders from "
                + "Maxwell's equations (docs/design/rigorous.md)" : "";
        reporter.warn(e.describe() + ": " + how + fix);
    }

    private static String number(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }

    /** A black (or nearly black) picture says so, and which option shows it. */
    private void warnIfDark(float[] luminance, Direction wi, double exposure, BrdfSettings settings,
                            double patchWidthUm, double patchHeightUm, Reporter reporter) {
        double brightest = 0;
        for (float value : luminance) {
            brightest = Math.max(brightest, value);
        }
        // an OpenEXR map is not exposed: no exposure can hide its light, only a map without any is worth a word
        boolean exposureShowsAll = picture.exposure.automatic() || outputIsExr();
        DarkMapNotice.check(brightest, AutoExposure.brightestDiffracted(luminance, picture.size, -wi.x(), -wi.y()),
                exposure, exposureShowsAll, settings, patchWidthUm, patchHeightUm,
                picture.size).ifPresent(n -> {
                    if (n.warning()) {
                        reporter.warn(n.text());
                    } else {
                        reporter.info(n.text());
                    }
                });
    }
}
