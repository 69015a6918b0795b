package diffract.app;

import diffract.app.jobs.BenchPiece;
import diffract.app.jobs.PieceFolder;
import diffract.app.jobs.PieceManifest;
import diffract.app.jobs.SplitCommand;
import diffract.app.jobs.TileOptions;
import diffract.app.options.CacheOption;
import diffract.app.options.GpuOption;
import diffract.app.options.OptionTypes;
import diffract.app.options.PatchOptions;
import diffract.app.options.QuietOption;
import diffract.bench.BenchConfig;
import diffract.bench.BenchPatch;
import diffract.bench.BenchResult;
import diffract.bench.BenchRunner;
import diffract.bench.FilteringTargets;
import diffract.bench.ParetoPlot;
import diffract.bench.ReferenceMaps;
import diffract.bench.ReferenceSet;
import diffract.bench.ResultsTable;
import diffract.bench.SweepPlan;
import diffract.bench.Targets;
import diffract.jrtr.contexts.GLInfo;
import diffract.jrtr.contexts.HeadlessGL;
import diffract.optics.BrdfSettings;
import diffract.optics.MapBand;
import diffract.optics.Methods;
import diffract.optics.Variant;
import diffract.optics.settings.TermFormat;
import diffract.pipeline.NamedPatch;
import diffract.util.DiskCache;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.function.Function;

/**
 * {@code diffract bench}: sweeps GPU configurations (variant, Taylor terms, lambda step, window radius, term texture
 * format, image size, patch), measures each one's median GPU time per frame and its CIEDE2000 error against the
 * CPU reference, and writes {@code results.csv}, {@code results.md}, {@code pareto.md}, {@code targets.md},
 * {@code machine.txt} and the Pareto plot {@code pareto.png} into the output folder. With {@code --tile I/N --pieces
 * DIR} it measures only run I of N runs of the sweep's configurations, into a piece that {@code merge} assembles with
 * the others into those files ({@link SplitCommand}: {@code submit} runs it in pieces).
 */
@Command(name = "bench", mixinStandardHelpOptions = true)
final class BenchCommand implements SplitCommand, Callable<Integer> {
    /** A measured patch's light azimuth: ridges along x, as a snake patch scanned along its scale. */
    private static final double FILE_PATCH_PHI_DEG = 90;

    @Mixin GpuOption gpu;

    @Option(names = {"-o", "--output"}, paramLabel = "DIR") Path outputDir;

    @Mixin TileOptions tiles;
    @Spec CommandSpec spec;

    @Option(names = "--quick") boolean quick;

    @Option(names = "--patches", defaultValue = BenchPatch.DEFAULT_NAMES, paramLabel = "LIST", split = ",",
            completionCandidates = OptionTypes.PatchNames.class)
    List<String> patches;

    @Option(names = "--variants", paramLabel = "LIST", split = ",", converter = VariantConverter.class)
    List<Variant> variants;

    @Option(names = "--size", defaultValue = "64", paramLabel = "S") int sizePx;

    @Option(names = "--large-size", defaultValue = "128", paramLabel = "S") int largeSizePx;

    @Option(names = "--terms", paramLabel = "LIST", split = ",") List<Integer> termsList;

    @Option(names = "--lambda-steps", paramLabel = "LIST", split = ",") List<Double> stepsList;

    @Option(names = "--window-radii", paramLabel = "LIST", split = ",") List<Integer> radiiList;

    @Option(names = "--texture-formats", paramLabel = "LIST", split = ",") List<TermFormat> formatsList;

    @Option(names = "--sizes", paramLabel = "LIST", split = ",") List<Integer> sizesList;

    @Option(names = "--coherence-length", defaultValue = "65", paramLabel = "UM") double coherenceLengthUm;

    @Option(names = "--lambda-min", defaultValue = "380", paramLabel = "NM") double lambdaMinNm;

    @Option(names = "--lambda-max", defaultValue = "780", paramLabel = "NM") double lambdaMaxNm;

    @Mixin QuietOption quiet;
    @Mixin CacheOption cache;

    @Option(names = "--gpu-suite") boolean gpuSuite;

    @Option(names = "--filtering") boolean filtering;

    @Option(names = "--baked-samples", paramLabel = "UV,W", converter = OptionTypes.BakedSamples.Converter.class)
    OptionTypes.BakedSamples bakedSamples;

    @Option(names = "--lights", paramLabel = "LIST", split = ",", defaultValue = "0,2") List<Double> lightsDeg;

    /** --filtering: one more patch beside --patches, read as every command reads one. */
    @Mixin PatchOptions patch;

    @Option(names = "--phi-i", paramLabel = "DEG") Double patchPhiDeg;

    @Option(names = "--suite-scene", paramLabel = "FILE") Path suiteScene;

    @Option(names = "--suite-scenes-only") boolean suiteScenesOnly;

    @Option(names = "--suite-size", paramLabel = "WxH", converter = OptionTypes.ImageSize.Converter.class)
    OptionTypes.ImageSize suiteSize;

    @Option(names = "--error-size", defaultValue = "128", paramLabel = "S") int errorSizePx;

    @Option(names = "--frames", defaultValue = "10", paramLabel = "N") int frames;

    @Override
    public Integer call() throws IOException {
        if (frames < diffract.jrtr.gl.GpuTimer.MIN_FRAMES) {
            throw new UserInputException("--frames takes at least " + diffract.jrtr.gl.GpuTimer.MIN_FRAMES
                    + " frames (their median is the time), got " + frames);
        }
        if (tiles.requested("which run of the sweep's configurations to measure")) {
            validateTile();
        } else {
            requireOutput();
        }
        if (gpuSuite && filtering) {
            throw new UserInputException("--gpu-suite and --filtering are two runs of their own: give one of them");
        }
        if (gpuSuite && (patch.given() || patchPhiDeg != null)) {
            throw new UserInputException("--gpu-suite draws its own maps and scenes: --patch, --synthetic and --phi-i "
                    + "add a patch to --filtering's");
        }
        if (gpuSuite) {
            HeadlessGL.require();
            long start = System.nanoTime();
            List<Variant> suiteVariants = variants == null ? GpuSuite.gpuVariants() : variants;
            int[] size = suiteSize == null ? null : new int[] {suiteSize.width(), suiteSize.height()};
            List<GpuSuite.Row> rows = new GpuSuite(outputDir, size, errorSizePx, frames, suiteVariants, suiteScene,
                    suiteScenesOnly, quiet.reporter()).run();
            System.out.printf(Locale.ROOT, "gpu suite: %d rows in %.0f s%nwrote %s, %s%n", rows.size(),
                    (System.nanoTime() - start) * 1e-9, outputDir.resolve("gpu-suite.csv"),
                    outputDir.resolve("gpu-suite.md"));
            return 0;
        }
        patch.validate();
        if (!filtering && (patch.given() || patchPhiDeg != null)) {
            throw new UserInputException("--patch, --synthetic and --phi-i add a patch to --filtering's: add "
                    + "--filtering, or name the sweep's patches with --patches");
        }
        if (filtering) {
            return filtering();
        }
        long start = System.nanoTime();
        Sweep sweep = sweep();
        List<BenchConfig> configs = sweep.configs();
        MapBand band = tiles.tile == null ? null : MapBand.of(tiles.tile.index(), tiles.tile.count(), configs.size());
        List<BenchConfig> measured = band == null ? configs : configs.subList(band.fromRow(), band.toRow());
        HeadlessGL.require();
        if (tiles.tile == null) {
            Files.createDirectories(outputDir);
        }
        Reporter reporter = quiet.reporter();
        reporter.info(String.format(Locale.ROOT, "bench: %d configurations%s on %d patches (%s sweep), coherence "
                        + "length %s um, output %s", measured.size(), tiles.tile == null ? ""
                        : " (" + band + " of " + configs.size() + ", piece " + tiles.tile + ")", sweep.patches().size(),
                quick ? "quick" : isCustom() ? "own" : "full", coherenceLengthUm,
                tiles.tile == null ? outputDir : tiles.pieces));
        ReferenceMaps references = new ReferenceMaps(DiskCache.user(), reporter);
        BenchRunner runner = new BenchRunner(references, reporter).keepMapsOf(Targets::needsMaps);
        Path csv = tiles.tile == null ? outputDir.resolve("results.csv") : null;
        List<BenchResult> done = new ArrayList<>();
        long work = System.nanoTime();
        List<BenchResult> results = runner.run(measured, sweep.patches(), sweep.base(), r -> {
            done.add(r);
            if (csv == null) {
                return;
            }
            try { // after every configuration: an interrupted run keeps its rows
                ResultsTable.writeCsv(csv, done, runner.glInfo());
            } catch (IOException e) {
                throw new UserInputException("cannot write " + csv + ": " + e.getMessage(), e);
            }
        });
        if (tiles.tile != null) {
            writePiece(sweep, band, results, runner.glInfo(), start, work);
            return 0;
        }
        String machine = machine(runner.glInfo());
        String targets = writeResults(sweep, results, runner.glInfo(), machine, runner::maps, references);
        System.out.printf(Locale.ROOT, "bench: %d configurations in %.0f s on %s%nwrote %s, %s, %s, %s%n%s",
                results.size(), (System.nanoTime() - start) * 1e-9, machine, csv, outputDir.resolve("results.md"),
                outputDir.resolve("targets.md"), outputDir.resolve("pareto.png"), targets);
        return 0;
    }

    /** The sweep the options name: its base settings, its patches by name and its configurations, in order. */
    record Sweep(BrdfSettings base, Map<String, BenchPatch> patches, List<BenchConfig> configs) {
        /** A content hash of the configurations, in order: pieces of one sweep agree on it. */
        String configurationsSha256() {
            return DiskCache.sha256Hex(String.join("\n", configs.stream().map(BenchConfig::key).toList())
                    .getBytes(StandardCharsets.UTF_8));
        }

        /** A content hash of the patches' height fields, in order. */
        String patchesSha256() {
            return DiskCache.sha256Hex(String.join("\n", patches.values().stream()
                    .map(p -> p.name() + " " + p.field().contentSha256()).toList()).getBytes(StandardCharsets.UTF_8));
        }
    }

    /** The sweep's settings and configurations (no GL, no measurement): what a run, a piece and merge agree on. */
    Sweep sweep() {
        if (sizePx < 8 || sizePx > 1024 || largeSizePx < 8 || largeSizePx > 1024) {
            throw new UserInputException("map sizes must be between 8 and 1024 pixels");
        }
        // the thesis' settings except the wavelength range and the coherence length asked for
        BrdfSettings base = BrdfSettings.thesis(Methods.Role.THESIS.method()).with(b -> b
                .lambdaRangeNm(lambdaMinNm, lambdaMaxNm).coherenceLengthUm(coherenceLengthUm));
        Map<String, BenchPatch> patchMap = new LinkedHashMap<>();
        for (BenchPatch p : BenchPatch.named(patches)) {
            patchMap.put(p.name(), p);
        }
        List<Variant> variantList = variants == null ? SweepPlan.sweptVariants(quick) : variants;
        for (Variant v : variantList) {
            if (!v.runsOnGpu()) {
                throw new UserInputException("the " + v.spec() + " is what the bench measures against; sweep "
                        + Methods.listed(Variant::runsOnGpu, "or"));
            }
        }
        List<BenchConfig> configs = SweepPlan.configs(new ArrayList<>(patchMap.keySet()), variantList, points(), base);
        return new Sweep(base, patchMap, configs);
    }

    /**
     * results.csv, results.md, pareto.md, targets.md, machine.txt and pareto.png of the measured rows; returns the
     * targets' table. {@code maps} gives the kept GPU maps of a configuration (null where none are kept).
     */
    private String writeResults(Sweep sweep, List<BenchResult> results, GLInfo gl, String machine,
                                Function<BenchConfig, List<float[]>> maps, ReferenceMaps references)
            throws IOException {
        ResultsTable.writeCsv(outputDir.resolve("results.csv"), results, gl);
        Files.writeString(outputDir.resolve("results.md"), ResultsTable.markdown(results), StandardCharsets.UTF_8);
        Files.writeString(outputDir.resolve("pareto.md"), ResultsTable.markdown(results, true), StandardCharsets.UTF_8);
        List<Targets.Outcome> outcomes = Targets.of(results, sizePx, maps,
                (patch, size) -> exposures(references, sweep.patches().get(patch), size, sweep.base()));
        String targets = Targets.markdown(outcomes);
        Files.writeString(outputDir.resolve("targets.md"), targets, StandardCharsets.UTF_8);
        Files.writeString(outputDir.resolve("machine.txt"), machine + "\n", StandardCharsets.UTF_8);
        ParetoPlot.write(outputDir.resolve("pareto.png"), results, "diffract bench: error against GPU time per frame ("
                + sizePx + "x" + sizePx + ", " + machineShort(gl) + ")");
        return targets;
    }

    /** With --tile: the piece's rows, in its manifest (no floats), into --pieces DIR. */
    private void writePiece(Sweep sweep, MapBand band, List<BenchResult> results, GLInfo gl, long startNanos,
                            long workNanos) throws IOException {
        TileOptions.Tile tile = tiles.tile;
        long done = System.nanoTime();
        PieceFolder.write(tiles.pieces, pieceManifest(sweep, tile, TileOptions.argumentsWithoutTile(spec), results,
                machine(gl), gl), new float[0]);
        // submit reads this line: the piece's fixed cost (loading, terms, reference maps) against its work
        System.out.printf(Locale.ROOT, "wrote piece %s (configurations %s of %d) into %s: setup %.2f s, work %.2f s%n",
                tile, band, sweep.configs().size(), tiles.pieces, (workNanos - startNanos) * 1e-9,
                (done - workNanos) * 1e-9);
    }

    /**
     * The manifest of piece {@code tile} of a sweep run with {@code arguments} (less --tile and --pieces): what merge
     * compares (the sweep's base settings, its configurations and patches) and the rows it measured.
     */
    static PieceManifest pieceManifest(Sweep sweep, TileOptions.Tile tile, List<String> arguments,
                                       List<BenchResult> results, String machine, GLInfo gl) {
        MapBand band = MapBand.of(tile.index(), tile.count(), sweep.configs().size());
        Map<String, String> settings = new LinkedHashMap<>();
        settings.put("version", diffract.util.Version.VERSION);
        settings.put("base", sweep.base().toString());
        settings.put("configurationsSha256", sweep.configurationsSha256());
        return new PieceManifest(PieceManifest.FORMAT, "bench", tile.index(), tile.count(), band.fromRow(),
                band.toRow(), sweep.configs().size(), 0, sweep.patchesSha256(), settings, Map.of(), arguments, null,
                null, BenchPiece.of(results, machine, gl));
    }

    /**
     * Merge's half of a split sweep: the pieces' rows, in the sweep's order, written as one run writes them
     * (results.csv from the same doubles, bit for bit). The targets' direct comparison of NMM with FLSS at 1 nm needs
     * both configurations' maps in one process and is left out (its columns read "-"); machine.txt holds the
     * pieces' machine lines, one per distinct line.
     */
    void writeMerged(List<PieceManifest> pieces, Reporter reporter) throws IOException {
        requireOutput();
        Sweep sweep = sweep();
        PieceManifest first = pieces.get(0);
        if (!sweep.configurationsSha256().equals(first.settings().get("configurationsSha256"))
                || !sweep.base().toString().equals(first.settings().get("base"))) {
            throw new UserInputException("merge: the pieces' options give another sweep in this diffract than in the "
                    + "one that measured them: compute them again with this diffract");
        }
        List<BenchResult> results = new ArrayList<>();
        List<String> machines = new ArrayList<>();
        GLInfo gl = null;
        String glPiece = null;
        for (PieceManifest m : pieces) {
            if (m.bench() == null) {
                throw new UserInputException("merge: bench piece " + m.label() + " holds no rows: compute it again");
            }
            Map<String, BenchConfig> ofPiece = new LinkedHashMap<>(); // its own run of configurations
            sweep.configs().subList(m.from(), m.to()).forEach(c -> ofPiece.put(c.key(), c));
            results.addAll(m.bench().results(ofPiece, m.label()));
            if (!machines.contains(m.bench().machine())) {
                machines.add(m.bench().machine());
            }
            GLInfo pieceGl = m.bench().glInfo();
            if (pieceGl != null) {
                if (gl != null && !(gl.renderer().equals(pieceGl.renderer())
                        && gl.version().equals(pieceGl.version()))) {
                    throw new UserInputException("merge: bench pieces " + glPiece + " and " + m.label() + " ran on "
                            + "different OpenGL (" + machineShort(gl) + "; " + machineShort(pieceGl) + "): their "
                            + "times do not compare; measure every piece on one kind of GPU");
                }
                gl = pieceGl;
                glPiece = m.label();
            }
        }
        Files.createDirectories(outputDir);
        String targets = writeResults(sweep, results, gl, String.join("\n", machines), c -> null,
                new ReferenceMaps(DiskCache.user(), reporter));
        reporter.info("merged bench: targets.md leaves out the direct comparison of NMM with FLSS at 1 nm (it needs "
                + "both configurations' maps in one process)\n" + targets);
    }

    /** -o DIR and the files of fixed name the run writes into it can be written. */
    private void requireOutput() {
        if (outputDir == null) {
            throw new UserInputException("bench needs -o DIR, the folder its results go to; with --tile I/N --pieces "
                    + "DIR it measures one piece of the sweep instead");
        }
        OutputPaths.require(outputs());
    }

    /** --tile splits the sweep (not the GPU suite or the filtering targets) and writes no -o. */
    private void validateTile() {
        if (gpuSuite || filtering) {
            throw new UserInputException("--tile splits the sweep's configurations; --gpu-suite and --filtering run "
                    + "whole: drop --tile and --pieces");
        }
        if (outputDir != null) {
            throw new UserInputException("--tile writes one piece into --pieces " + tiles.pieces + "; the bench's "
                    + "files are written by 'diffract merge " + tiles.pieces + " -o DIR': drop -o");
        }
        tiles.requireSplittable(sweep().configs().size(), "the sweep has only " + sweep().configs().size()
                + " configurations");
    }

    @Override
    public TileOptions tiles() {
        return tiles;
    }

    /** What {@code submit} checks before it starts any worker: the options as one run would, and the split. */
    @Override
    public void validateSplit(int pieceCount) {
        if (frames < diffract.jrtr.gl.GpuTimer.MIN_FRAMES) {
            throw new UserInputException("--frames takes at least " + diffract.jrtr.gl.GpuTimer.MIN_FRAMES
                    + " frames (their median is the time), got " + frames);
        }
        if (gpuSuite || filtering) {
            throw new UserInputException("submit splits the bench's sweep into runs of its configurations; "
                    + "--gpu-suite and --filtering run whole: run bench alone");
        }
        requireOutput();
        int configurations = sweep().configs().size();
        if (pieceCount > configurations) {
            throw new UserInputException("--piece-count " + pieceCount + ": the sweep has only " + configurations
                    + " configurations to split");
        }
    }

    @Override
    public Result result() {
        return Result.to(outputDir, sweep().configs().size(), "configurations", quiet.quiet);
    }

    /** The filtering targets ({@link FilteringTargets}): a table per patch and light. */
    private Integer filtering() throws IOException {
        if (sizePx < 8 || sizePx > 512) {
            throw new UserInputException("--size of the filtering maps must be between 8 and 512 pixels");
        }
        for (double d : lightsDeg) {
            new diffract.optics.illumination.LightSource(d); // a refused size fails before any work
        }
        List<BenchPatch> list = new ArrayList<>(BenchPatch.named(patches));
        Reporter reporter = quiet.reporter();
        if (patch.given()) {
            NamedPatch named = patch.load(null, reporter);
            double phiDeg = patchPhiDeg != null ? patchPhiDeg
                    : patch.file != null ? FILE_PATCH_PHI_DEG : patch.periodAzimuthDeg(null);
            // a file by its name less the extension; a patch made by code by its catalogue name and changes
            String name = patch.file != null ? named.name().replaceFirst("\\.[^.]*$", "") : named.name();
            list.add(new BenchPatch(name, named.meanSubtracted(), phiDeg));
        }
        HeadlessGL.require();
        Files.createDirectories(outputDir);
        BrdfSettings lobes = BrdfSettings.thesis(Methods.Role.FILTERING.method()).with(b -> b
                .lambdaRangeNm(lambdaMinNm, lambdaMaxNm).coherenceLengthUm(coherenceLengthUm));
        int bakedUv = bakedSamples == null ? FilteringTargets.DEFAULT_BAKED_UV_SAMPLES : bakedSamples.uv();
        int bakedW = bakedSamples == null ? 0 : bakedSamples.w();
        FilteringTargets targets = new FilteringTargets(new ReferenceMaps(DiskCache.user(), reporter), lobes, sizePx,
                FilteringTargets.ROUNDS, frames, bakedUv, bakedW, reporter);
        int total = list.size() * lightsDeg.size();
        List<FilteringTargets.Row> done = new ArrayList<>();
        long start = System.nanoTime();
        reporter.progress("filtering targets", 0);
        List<FilteringTargets.Row> rows = targets.run(list, lightsDeg, r -> {
            done.add(r);
            reporter.progress("filtering targets", done.size() / (double) total);
            try { // after every row: an interrupted run keeps its rows
                Files.writeString(outputDir.resolve("filtering.csv"), FilteringTargets.csv(done, targets.glInfo()),
                        StandardCharsets.UTF_8);
            } catch (IOException e) {
                throw new UserInputException("cannot write " + outputDir.resolve("filtering.csv") + ": "
                        + e.getMessage(), e);
            }
        });
        String md = FilteringTargets.markdown(rows, sizePx, lobes)
                + "\n" + machine(targets.glInfo()) + "\n";
        Files.writeString(outputDir.resolve("filtering.md"), md, StandardCharsets.UTF_8);
        System.out.printf(Locale.ROOT, "bench --filtering: %d rows in %.0f s%nwrote %s, %s%n%s", rows.size(),
                (System.nanoTime() - start) * 1e-9, outputDir.resolve("filtering.csv"),
                outputDir.resolve("filtering.md"), md);
        return 0;
    }

    /** The output folder and the files of fixed name the run writes into it. */
    private OutputPaths.Output[] outputs() {
        List<String> names = gpuSuite ? List.of("gpu-suite.csv", "gpu-suite.md")
                : filtering ? List.of("filtering.csv", "filtering.md")
                : List.of("results.csv", "results.md", "pareto.md", "targets.md", "machine.txt", "pareto.png");
        List<OutputPaths.Output> outputs = new ArrayList<>();
        outputs.add(OutputPaths.folder("-o", outputDir));
        for (String name : names) {
            outputs.add(OutputPaths.file("-o", outputDir.resolve(name), name, name.substring(name.lastIndexOf('.'))));
        }
        return outputs.toArray(OutputPaths.Output[]::new);
    }

    private boolean isCustom() {
        return termsList != null || stepsList != null || radiiList != null || formatsList != null || sizesList != null;
    }

    private List<SweepPlan.Point> points() {
        if (isCustom()) {
            if (quick) {
                throw new UserInputException("--quick has its own grid: leave out --terms, --lambda-steps, "
                        + "--window-radii, --texture-formats and --sizes, or --quick");
            }
            SweepPlan.Point t = SweepPlan.thesis(sizePx);
            return SweepPlan.grid(or(termsList, t.terms()), or(stepsList, t.lambdaStepNm()),
                    or(radiiList, t.windowRadius()), or(formatsList, t.textureFormat()), or(sizesList, sizePx));
        }
        return quick ? SweepPlan.quick(sizePx) : SweepPlan.full(sizePx, largeSizePx);
    }

    private static <T> List<T> or(List<T> given, T fallback) {
        return given == null ? List.of(fallback) : given;
    }

    /** A variant by name (the reference is refused later, with the reason). */
    static final class VariantConverter implements picocli.CommandLine.ITypeConverter<Variant> {
        @Override
        public Variant convert(String text) {
            try {
                return Variant.parse(text);
            } catch (UserInputException e) {
                throw new picocli.CommandLine.TypeConversionException(e.getMessage());
            }
        }
    }

    private static List<Double> exposures(ReferenceMaps references, BenchPatch patch, int size, BrdfSettings base) {
        return ReferenceSet.of(references, patch, BenchRunner.LIGHTS_DEG, size, base).exposures();
    }

    /** CPU model and cores (/proc/cpuinfo) and the GL renderer. */
    static String machine(GLInfo gl) {
        return Runtime.getRuntime().availableProcessors() + " CPU cores (" + cpuModel() + "), "
                + (gl == null ? "no GL" : gl.renderer() + ", OpenGL " + gl.version());
    }

    /** For plot titles: the renderer and the OpenGL version string. */
    static String machineShort(GLInfo gl) {
        return gl == null ? "no GL" : gl.renderer() + ", OpenGL " + gl.version();
    }

    private static String cpuModel() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/cpuinfo"))) {
                if (line.startsWith("model name")) {
                    return line.substring(line.indexOf(':') + 1).trim();
                }
            }
        } catch (IOException | RuntimeException e) {
            // not Linux: the model stays unknown
        }
        return "unknown CPU";
    }
}
