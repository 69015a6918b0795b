package diffract.render;

import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.illumination.DiscFootprint;

/**
 * The baked table of the lobes method under a disc light ({@code baked_disc.glsl}, docs/measurements/filtering.md section 8): the
 * table holds the point light's cell averages, and a lookup integrates the disc itself, per pixel, over the running
 * sums of the table's rows along u ({@link #rowSums}). So one table serves every disc size and direction, and the
 * oblique light's ellipse, its density 1 / (Omega d_z), the gain factor, the shadowing and w follow the disc's
 * directions, as the lobes method's {@code DiscFootprint} does lobe by lobe.
 *
 * <p>The disc's ellipse in (u, v) is cut into rows along v and each row into pieces along u: a piece's integral is the
 * difference of two running sums (exact along u for the table's interpolant), weighted by the density, the gain
 * ratio and w of the piece's centre direction. Rows are a table sample apart, {@link #MIN_ROWS} to {@link #ROWS_MAX}
 * of them, a power of two samples apart beyond {@link #FINE_ROWS_MAX}; pieces are at most {@link #PIECE_WIDTH_DEG}
 * wide, at most {@link #PIECES_MAX} a row. A disc narrow next to
 * the pixel's footprint is the Gaussian of its covariance instead, blended between {@link #gaussianBelow} and
 * {@link #edgeAbove} (a map pixel's box and a surface's Gaussian footprint blend differently). Each row is read over
 * the footprint's Gaussian (a mip level), except in a BRDF map under a disc
 * narrower than {@link #BOX_BELOW} footprint spreads: there the rows are averaged over the map pixel's box, by the
 * midpoint rule on nodes at most {@link #BOX_NODE_TEXELS} samples apart along u and v, read at level 0 where the
 * running sums plus half a sample of the table give the integral up to a cell's edge, exact between the edges
 * (docs/design/filtering.md, section 8).
 *
 * <table>
 *   <caption>Its defines (DiffractionShaders) and uniforms (DiffractionMaterials)</caption>
 *   <tr><th>name</th><th>what</th></tr>
 *   <tr><td>{@code BAKED_DISC}, {@code LIGHT_DISC}</td><td>the lookup integrates the settings' disc</td></tr>
 *   <tr><td>{@code DISC_ROWS_MAX}, {@code DISC_MIN_ROWS}, {@code DISC_FINE_ROWS_MAX}, {@code DISC_PIECES_MAX},
 *   {@code DISC_PIECE_UV}</td>
 *   <td>the constants below; the piece's width as sin of it</td></tr>
 *   <tr><td>{@code bakedLayers}</td><td>the table, mip-mapped per w slice (for the Gaussian of a narrow disc and
 *   for lights other than the disc)</td></tr>
 *   <tr><td>{@code bakedRowSums}</td><td>the running sums, RGB32F, mip-mapped per w slice</td></tr>
 *   <tr><td>{@code DISC_TABLE_GAUSSIAN_BELOW}, {@code DISC_TABLE_EDGE_ABOVE}</td>
 *   <td>{@link #gaussianBelow}, {@link #edgeAbove} of the program's pixels (a BRDF map's or a surface's)</td></tr>
 *   <tr><td>{@code DISC_TABLE_BOX_BELOW}, {@code DISC_BOX_NODES_MAX}, {@code DISC_BOX_NODE_TEXELS}</td>
 *   <td>{@link #BOX_BELOW}, {@link #BOX_NODES_MAX}, {@link #BOX_NODE_TEXELS}</td></tr>
 *   <tr><td>{@code lightHalfAngleRad}</td><td>the disc's half-angle R</td></tr>
 * </table>
 */
public final class BakedDisc {
    /** The most rows a disc is cut into. */
    public static final int ROWS_MAX = 64;
    /** The fewest rows a disc is cut into (a disc narrower than a table sample). */
    public static final int MIN_ROWS = 4;
    /**
     * A disc wider than this many table samples along v is cut into rows 2^L samples apart, read at mip level L or
     * coarser, so that it takes at most this many rows (and at least half as many): the midpoint rule across v sums
     * a level's linear interpolant exactly where the rows are its texels apart, and the level's blur of 2^L samples
     * is small next to the disc. At 513 samples a 20-degree disc takes 20 to 23 rows instead of 39 to 45: 1.7 to 2.3
     * times faster on llvmpipe, 0.04 to 0.13 further from the CPU lobes method (docs/design/filtering.md, section 8).
     */
    public static final int FINE_ROWS_MAX = 24;
    /** The most pieces a row is cut into. */
    public static final int PIECES_MAX = 2;
    /** The widest piece, in degrees of the disc. */
    public static final double PIECE_WIDTH_DEG = 5;
    /**
     * In a BRDF map, a disc whose minor semi-axis b is below this many of the footprint's spreads s (along b) is the
     * Gaussian of its covariance; see {@link #EDGE_ABOVE}.
     */
    public static final double GAUSSIAN_BELOW = 0.5;
    /**
     * In a BRDF map, above this b / s the disc is cut into rows; between, the two are blended. Lower than the lobes
     * method's ({@code DiscFootprint}), whose Gaussian takes a map pixel's box exactly: the table's Gaussian of the
     * disc and the box together spreads a disc as wide as a pixel over its neighbours, where the rows keep its edge
     * (docs/measurements/bench/disc-lobes.md).
     */
    public static final double EDGE_ABOVE = 1.5;
    /**
     * Below this b / s a BRDF map's rows average the pixel's box over nodes instead of reading it as a Gaussian: a
     * disc this narrow is under about three pixels across, its edge runs through the pixels beside each order, and
     * there the box's Gaussian and the box part most (the Gaussian reads a grating's specular order on the corner of
     * four pixels 12 % dim, and misplaces a 4-degree disc's edge in a 64 px map: docs/design/filtering.md, section 8).
     * Above it the box is a small part of the disc, and its nodes would multiply the cost of every row.
     */
    public static final double BOX_BELOW = 5;
    /** The most nodes along each axis over which a map pixel's box is averaged. */
    public static final int BOX_NODES_MAX = 8;
    /**
     * The box's nodes are at most this many table samples apart along each axis, and at least 2 (a 64 px map's pixel
     * is 4 samples of a 513 table wide: 2 x 2 nodes). Nodes 1 sample apart measured no better on the bench patches and
     * cost 4 times the lookups (docs/design/filtering.md, section 8).
     */
    public static final double BOX_NODE_TEXELS = 2;

    private BakedDisc() {
    }

    /**
     * The b / s below which the disc is its Gaussian, for a pixel of a BRDF map (a box) or of a surface. A surface's
     * pixel footprint is a Gaussian, which the lobes method takes too: there the table blends as {@code DiscFootprint}
     * does, from 1 to 3, and draws the viewer's sphere under the sun at 800 x 600 closer to the lobes method
     * (CIEDE2000 0.26 against 0.41 blended from 0.5 to 1.5) in about 100 ms a frame instead of 166 on llvmpipe
     * (docs/design/filtering.md, section 8).
     */
    public static double gaussianBelow(boolean mapPixel) {
        return mapPixel ? GAUSSIAN_BELOW : DiscFootprint.GAUSSIAN_BELOW;
    }

    /** The b / s above which the disc is cut into rows, for a pixel of a BRDF map or of a surface (as above). */
    public static double edgeAbove(boolean mapPixel) {
        return mapPixel ? EDGE_ABOVE : DiscFootprint.EDGE_ABOVE;
    }

    /** Whether a table drawn with {@code settings} is looked up under their disc (a filtered table, a disc light). */
    public static boolean integrates(BrdfSettings settings, boolean filteredTable) {
        return filteredTable && settings.illumination().light().isDisc();
    }

    /**
     * The settings a table is baked and cached with: under a disc, the point light (the lookup adds the disc); under
     * a Gaussian light or a point, the settings' own.
     */
    public static BrdfSettings heldBy(BrdfSettings settings) {
        return settings.illumination().light().isDisc() ? settings.with(b -> b.lightSizeDeg(0)) : settings;
    }

    /** sigma_a of the light a filtered table drawn with {@code settings} holds: 0 under a disc (a point table). */
    public static double heldSigmaRad(BrdfSettings settings) {
        return heldBy(settings).illumination().light().sigmaRad();
    }

    /**
     * The running sums of the table's rows along u: at sample i of row (v_j, w_k), the integral of the table from
     * u_min to u_i, each sample standing for its cell of width h = (u_max - u_min) / (n - 1): h (sum of the samples
     * before i + half of sample i). Linear interpolation between samples is then the integral of the table held
     * constant on the cells between sample centres, whose total is the table's. Summed in double, stored as float32.
     *
     * @param rgb the table's values, RGB, u fastest, then v, then w
     */
    public static float[] rowSums(float[] rgb, BakedGrid grid) {
        int n = grid.uvSamples();
        int rows = grid.wSamples() * n;
        double h = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (n - 1);
        float[] sums = new float[rgb.length];
        for (int row = 0; row < rows; row++) {
            for (int c = 0; c < 3; c++) {
                double before = 0;
                for (int i = 0; i < n; i++) {
                    int at = 3 * (row * n + i) + c;
                    sums[at] = (float) (h * (before + 0.5 * rgb[at]));
                    before += rgb[at];
                }
            }
        }
        return sums;
    }
}
