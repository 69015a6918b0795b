package diffract.render;

import diffract.jrtr.textures.FloatTexture3D;
import diffract.jrtr.textures.Texture;
import diffract.util.Reporter;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;

/**
 * The baked tables of one patch's terms ({@link DiffractionTextures#tables}): the baked method's table (BAKED only)
 * with its textures, each made on first use and owned here, and the lobes method's table, which environment lights
 * wider than the lobes method sums read (baked on request).
 *
 * <ul>
 *   <li>{@code bakedXyz}: a table of FLSS, XYZ(u, v, w) trilinear ({@link BakedTable}), or {@code bakedLayers}, the
 *       mip-mapped table of the lobes method;</li>
 *   <li>{@code bakedRowSums}: the running sums of that table's rows ({@link BakedDisc}), for a disc light;</li>
 *   <li>{@code discTable}: that table spread by a wide disc light ({@link DiscTable}), one per light size drawn.</li>
 * </ul>
 */
public final class TableTextures {
    private final BakedTable baked;
    /** Bakes the lobes method's filtered table of these terms on request (null on the phase-centred path). */
    private final Function<Reporter, BakedTable> lobesTableSource;
    private FloatTexture3D texture;
    private FloatTexture3D rowSums;
    private final Map<Double, FloatTexture3D> discTables = new LinkedHashMap<>();

    TableTextures(BakedTable baked, Function<Reporter, BakedTable> lobesTableSource) {
        this.baked = baked;
        this.lobesTableSource = lobesTableSource;
    }

    /** The baked method's table (BAKED only), else null. */
    public BakedTable baked() {
        return baked;
    }

    /** The baked table's texture (BAKED only), made on first use. */
    public synchronized FloatTexture3D texture() {
        if (texture == null) {
            texture = baked.texture();
        }
        return texture;
    }

    /** The running sums of the baked table's rows ({@link BakedTable#rowSumsTexture}), made on first use. */
    public synchronized FloatTexture3D rowSums() {
        if (rowSums == null) {
            rowSums = baked.rowSumsTexture();
        }
        return rowSums;
    }

    /**
     * The baked table spread by the disc of half-angle {@code halfAngleRad} ({@link BakedTable#discTable}), made on
     * first use per light size.
     */
    public synchronized FloatTexture3D discTable(double halfAngleRad) {
        return discTables.computeIfAbsent(halfAngleRad, r -> baked.discTable(r).texture());
    }

    /** The (u, v) samples per axis of {@link #discTable}. */
    public int discTableSide(double halfAngleRad) {
        return discTable(halfAngleRad).width();
    }

    /** The textures made so far, which their owner releases with these tables. */
    public synchronized List<Texture> made() {
        List<Texture> made = new ArrayList<>(discTables.values());
        if (texture != null) {
            made.add(texture);
        }
        if (rowSums != null) {
            made.add(rowSums);
        }
        return made;
    }

    /**
     * The baked table of the lobes method for the settings these tables were made for (cached by {@link BakedTables},
     * baked on the first request with progress on {@code reporter}): what environment lights wider than the lobes
     * method takes read (surface_stage.glsl); empty on the phase-centred path, which has no table, and where the
     * settings do not filter (the table would be FLSS's).
     */
    public Optional<BakedTable> lobesTable(Reporter reporter) {
        if (lobesTableSource == null) {
            return Optional.empty();
        }
        return Optional.of(lobesTableSource.apply(reporter)).filter(BakedTable::filtered);
    }
}
