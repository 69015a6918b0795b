package diffract.app;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import diffract.app.options.BrdfOptions;
import diffract.app.options.CacheOption;
import diffract.app.options.PatchOptions;
import diffract.app.options.QuietOption;
import diffract.colour.MirrorNormalisation;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.RadiometricGain;
import diffract.optics.Variant;
import diffract.optics.baked.BrdfTable;
import diffract.optics.illumination.GainFactor;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.PixelFilter;
import diffract.pipeline.DiffractionPipeline;
import diffract.pipeline.NamedPatch;
import diffract.util.NpyFile;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;

/** {@code diffract export --mitsuba}: the BRDF of a patch as a table that Mitsuba 3 renders (docs/guide/mitsuba.md). */
@Command(name = "export", mixinStandardHelpOptions = true, abbreviateSynopsis = true)
final class ExportCommand implements Callable<Integer> {
    /** The header's format name; the plugin refuses any other. */
    static final String FORMAT = "diffract-brdf-table";
    static final int VERSION = 1;

    @Mixin PatchOptions patch;
    @Mixin BrdfOptions brdf;
    @Mixin QuietOption quiet;
    @Mixin CacheOption cache;

    @Option(names = "--mitsuba", required = true, paramLabel = "OUT.json") Path mitsuba;

    /** The table's settings: the scenes' (ViewerOptions#defaults, radiometric) under a point light. */
    static BrdfSettings base() {
        BrdfSettings thesis = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX));
        return thesis.with(b -> b.spectral(thesis.spectral().withNormalisation(MirrorNormalisation.ENERGY)));
    }

    @Override
    public Integer call() throws IOException {
        patch.validateRequired();
        brdf.validate();
        BrdfSettings settings = brdf.apply(base());
        if (settings.variant() != Variant.LOBES) {
            throw new UserInputException("--variant: export tabulates the lobes method (it averages each table cell, "
                    + "so no order falls between nodes); leave out --variant or give --variant lobes");
        }
        if (!settings.illumination().light().isPoint()) {
            throw new UserInputException("--light-size-deg: the table is the BRDF under a point light; give the "
                    + "renderer's emitter the light's size instead");
        }
        Path data = dataFile(mitsuba);
        OutputPaths.require(OutputPaths.file("--mitsuba", mitsuba, "table.json", ".json"),
                OutputPaths.file("--mitsuba", data, "table.npy", ".npy"));
        Reporter reporter = quiet.reporter();
        long start = System.nanoTime();
        NamedPatch named = patch.load("", reporter);
        HeightField field = named.meanSubtracted();
        BakedGrid grid = BakedGrid.of(settings, field.maxAbsHeightUm());
        if (3 * grid.texels() > Integer.MAX_VALUE - 8) {
            throw new UserInputException(String.format(Locale.ROOT, "a %d x %d x %d table holds more floats than one "
                    + "array can (2^31); give fewer with --baked-samples UV,W", grid.uvSamples(), grid.uvSamples(),
                    grid.wSamples()));
        }
        MemoryCheck.export(field, settings, grid);
        DiffractionPipeline pipeline = DiffractionPipeline.cached(named, settings.spectral().lambdaMinNm());
        DiffractionBrdf cpu = pipeline.cpuBrdf(settings, settings.spectral().lambdaMinNm(), reporter);
        BrdfTable table = BrdfTable.of(cpu, grid, reporter);
        NpyFile.writeFloat32(data, table.rgb(), grid.wSamples(), grid.uvSamples(), grid.uvSamples(), 3);
        new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT).writeValue(mitsuba.toFile(),
                header(table, settings, named, field, data));
        System.out.printf(Locale.ROOT, "wrote %s and %s (%d x %d x %d nodes, %.1f MB) in %.1f s%n", mitsuba, data,
                grid.uvSamples(), grid.uvSamples(), grid.wSamples(), 12.0 * grid.texels() / 1e6,
                (System.nanoTime() - start) * 1e-9);
        return 0;
    }

    /** OUT.npy beside OUT.json. */
    static Path dataFile(Path header) {
        String name = header.getFileName() == null ? "table.json" : header.getFileName().toString();
        String stem = name.toLowerCase(Locale.ROOT).endsWith(".json") ? name.substring(0, name.length() - 5) : name;
        return header.resolveSibling(stem + ".npy");
    }

    /** What the plugin needs to evaluate the table, and what it was made from. */
    private Map<String, Object> header(BrdfTable table, BrdfSettings settings, NamedPatch named, HeightField field,
                                       Path data) {
        BakedGrid grid = table.grid();
        Map<String, Object> h = new LinkedHashMap<>();
        h.put("format", FORMAT);
        h.put("version", VERSION);
        h.put("data", data.getFileName().toString());
        h.put("layout", "float32 [w][v][u][rgb], C order; node i of n at -2 + 4 i / (n - 1) (u, v), "
                + "w at -2 + 2 k / (n_w - 1)");
        h.put("shape", List.of(grid.wSamples(), grid.uvSamples(), grid.uvSamples(), 3));
        h.put("uv_range", List.of(BakedGrid.U_MIN, BakedGrid.U_MAX));
        h.put("w_range", List.of(BakedGrid.W_MIN, BakedGrid.W_MAX));
        h.put("colour", "linear sRGB (Rec. 709 primaries, D65 white), unclipped");
        h.put("value", "the lobes method's spectral factor of the relative BRDF at (u, v, w) = -omega_i - omega_r, "
                + "averaged over the node's cell in (u, v); times gain_factor x shadowing it is the relative BRDF "
                + "(brdfmap's values), times radiometric_gain / pi the BRDF in 1/sr");
        h.put("refractive_index", table.refractiveIndex());
        h.put("schlick_r0", GainFactor.schlickR0(table.refractiveIndex()));
        h.put("gain", table.gain().label());
        h.put("radiometric_gain", RadiometricGain.of(settings));
        h.put("coherence_length_um", settings.illumination().coherenceLengthUm());
        h.put("lambda_nm", List.of(settings.spectral().lambdaMinNm(), settings.spectral().lambdaMaxNm()));
        h.put("normalisation", settings.spectral().normalisation().name().toLowerCase(Locale.ROOT));
        h.put("patch", named.name());
        h.put("patch_extent_um", List.of(field.widthUm(), field.heightExtentUm()));
        h.put("period_azimuth_deg", patch.periodAzimuthDeg(""));
        h.put("frame", "x along the height field's columns, y along its rows, z the normal");
        return h;
    }
}
