package diffract.render;

import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;
import diffract.util.DiskCache;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;

/**
 * A baked table as an entry of the disk cache ({@link DiskCache}, kind {@value #KIND}): its key and its payload.
 * The key holds what the table is made of: the terms' content hash, the settings as the in-memory cache compares
 * them (variant, term format and Fresnel model set to what a bake uses), the tabulated method, the grid, and a
 * hash of the bake program's GLSL text, so a changed shader bakes anew. The payload holds the grid, whether the
 * samples are filtered, the bake's seconds and the float32 samples exactly as baked, so a loaded table equals the
 * baked one bit for bit.
 */
final class BakedTableFile {
    /** The disk cache's kind of baked tables. */
    static final String KIND = "baked-tables";
    /** Bump when the bake's Java side (read-back layout, uniforms) or this payload changes, so old entries go unused. */
    static final int FORMAT = 1;

    private BakedTableFile() {
    }

    /**
     * The key of the table of {@code terms} baked with {@code keySettings} (already normalised as the in-memory key
     * is) of the method {@code tabulated}.
     */
    static DiskCache.Key key(TaylorTerms terms, BrdfSettings keySettings, Variant tabulated) {
        BakedGrid grid = BakedGrid.of(keySettings, terms.maxAbsHeightUm());
        BrdfSettings method = keySettings.with(b -> b.variant(tabulated).termFormat(TermFormat.RG32F));
        ShaderProgram program = DiffractionShaders.bakeProgram(method, method.highestOrderNeeded(terms.maxAbsHeightUm()),
                method.windowRadii(terms.cols() * terms.pixelSizeXUm(), terms.rows() * terms.pixelSizeYUm()));
        String programSha = DiskCache.sha256Hex((program.vertexShader().source().text() + "\u0000"
                + program.fragmentShader().source().text()).getBytes(StandardCharsets.UTF_8));
        return new DiskCache.Key(KIND, String.join("; ", "baked table format " + FORMAT,
                "method " + tabulated.spec(),
                "grid " + grid.uvSamples() + "x" + grid.uvSamples() + "x" + grid.wSamples(),
                "terms sha256 " + terms.contentSha256(), "settings " + keySettings, "bake program sha256 " + programSha));
    }

    /** Writes the table's payload. */
    static void write(BakedTable table, DataOutputStream out) throws IOException {
        out.writeInt(table.grid().uvSamples());
        out.writeInt(table.grid().wSamples());
        out.writeBoolean(table.filtered());
        out.writeDouble(table.bakeSeconds());
        DiskCache.writeFloats(out, table.values());
    }

    /**
     * Reads a payload written by {@link #write}, which must hold the grid and method the key names.
     *
     * @throws IOException when it holds another grid or method, or ends early
     */
    static BakedTable read(DataInputStream in, BakedGrid grid, Variant tabulated) throws IOException {
        int uv = in.readInt();
        int w = in.readInt();
        boolean filtered = in.readBoolean();
        double bakeSeconds = in.readDouble();
        if (uv != grid.uvSamples() || w != grid.wSamples() || filtered != tabulated.filtersLight()) {
            throw new IOException("it holds a " + uv + " x " + uv + " x " + w
                    + (filtered ? " filtered" : " point-sampled")
                    + " table, not the " + grid.uvSamples() + " x " + grid.uvSamples() + " x " + grid.wSamples() + " "
                    + tabulated.spec() + " one of its key");
        }
        float[] rgb = new float[Math.toIntExact(3 * grid.texels())];
        DiskCache.readFloats(in, rgb);
        return new BakedTable(grid, rgb, BakedTable.PRECISION, bakeSeconds, tabulated, 0);
    }
}
