package diffract.render;

import diffract.jrtr.scenegraph.Camera;
import diffract.jrtr.textures.FloatTexture3D;
import diffract.jrtr.scenegraph.Frustum;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.OffscreenTarget;
import diffract.jrtr.Renderer;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.util.Locale;

/**
 * The baked method's table: the spectral integral of the method it tabulates (FLSS or the lobes method), XYZ(u, v, w)
 * before the gain factor and shadowing, at the samples of a {@link BakedGrid}, baked on the GPU by that method's bake
 * pass ({@link GpuMethod#bakeFragmentPath}: its shader code per table sample, one w slice per frame, read back as
 * float32) and looked up trilinearly per fragment. The host keeps the float32 values (to upload into any GL
 * context); the GPU holds them as RGB16F by default: half precision rounds to 2^-11 relative (BakedVariantTest
 * holds the specular sample to 1e-3 of the CPU's FLSS), far below what the trilinear interpolation of narrow orders
 * costs (docs/measurements/baked.md).
 */
public final class BakedTable {
    /** The GPU format of the table. */
    public static final FloatTexture3D.Precision PRECISION = FloatTexture3D.Precision.FLOAT16;

    private final BakedGrid grid;
    private final float[] rgb;
    private final FloatTexture3D.Precision precision;
    private final double bakeSeconds;
    private final Variant tabulated;
    private final long shortCells;
    private float[] rowSums;
    /**
     * The tables spread by a disc ({@link #discTable}), worked out once per light size: the last two sizes kept (an A/B
     * split may draw two).
     */
    private final java.util.LinkedHashMap<Double, DiscTable> discTables = new java.util.LinkedHashMap<>(4, 0.75f,
            true) {
        @Override
        protected boolean removeEldestEntry(java.util.Map.Entry<Double, DiscTable> eldest) {
            return size() > 2;
        }
    };

    /**
     * @param tabulated  the method whose spectrum the samples hold: point samples, or cell and light averages where it
     *                   {@link Variant#filtersLight}
     * @param shortCells the cells whose lobes loops this GL ended early (they miss lobes): such a table is what this GL
     *                   bakes, not what the settings ask, so the disk cache does not keep it
     */
    BakedTable(BakedGrid grid, float[] rgb, FloatTexture3D.Precision precision, double bakeSeconds, Variant tabulated,
               long shortCells) {
        if (rgb.length != 3 * grid.texels()) {
            throw new IllegalArgumentException("table of " + grid + " needs " + 3 * grid.texels() + " floats, got "
                    + rgb.length);
        }
        this.grid = grid;
        this.rgb = rgb;
        this.precision = precision;
        this.bakeSeconds = bakeSeconds;
        this.tabulated = tabulated;
        this.shortCells = shortCells;
    }

    /**
     * Bakes the spectral XYZ of the method {@code tabulated} ({@link diffract.optics.Variant#bakeable}) with
     * {@code settings} (its terms, window, Taylor tolerance, wavelengths and light) over the grid the settings ask
     * for, in a hidden GL context of its own. A table of FLSS holds point samples; a table of a method that filters
     * (the lobes method) holds each sample averaged over its cell of the table (a box of 4 / (n - 1) in u and v) and
     * over the settings' Gaussian light (isotropic, sigma_a; the table does not know omega_i; a disc is left to the
     * lookup, which integrates it: the table holds the point light, {@link BakedDisc#heldBy}), and is mip-mapped for
     * lookups that average over a pixel's footprint (docs/design/filtering.md, section 8).
     */
    public static BakedTable bake(TaylorTerms terms, BrdfSettings settings, Variant tabulated,
                                  FloatTexture3D.Precision precision, Reporter reporter) {
        long start = System.nanoTime();
        BakedGrid grid = BakedGrid.of(settings, terms.maxAbsHeightUm());
        BrdfSettings method = BakedDisc.heldBy(settings).with(b -> b.variant(tabulated)
                .termFormat(TermFormat.RG32F));
        Material material = DiffractionMaterials.bake(DiffractionTextures.of(terms, method), method, grid);
        boolean filtered = tabulated.filtersLight();
        int n = grid.uvSamples();
        if (3 * grid.texels() > Integer.MAX_VALUE - 8) {
            throw new UserInputException(String.format(Locale.ROOT, "a %d x %d x %d baked table holds more samples than"
                    + " one array can (2^31 floats); use fewer samples", n, n, grid.wSamples()));
        }
        float[] rgb = new float[(int) (3 * grid.texels())];
        long shortCells = 0;
        ShapeNode quad = new ShapeNode(Shapes.fullScreenQuad(), material);
        String task = String.format(Locale.ROOT, "baking the %d x %d x %d table", n, n, grid.wSamples());
        reporter.progress(task, 0);
        try (OffscreenTarget target = new OffscreenTarget(new Renderer(new Group("bake").add(quad), new Camera(),
                new Frustum()))) {
            for (int k = 0; k < grid.wSamples(); k++) {
                material.setFloat("bakeW", (float) grid.w(k));
                float[] rgba = target.renderRgba(n, n);
                for (int row = 0; row < n; row++) {
                    int j = n - 1 - row; // rows come top-down; the shader's pixel row j (from the bottom) is v_j
                    for (int i = 0; i < n; i++) {
                        int from = 4 * (row * n + i);
                        int to = 3 * (i + n * (j + n * k));
                        rgb[to] = rgba[from];
                        rgb[to + 1] = rgba[from + 1];
                        rgb[to + 2] = rgba[from + 2];
                        if (filtered && rgba[from + 3] == 0) {
                            shortCells++; // the shader's loops were ended early (lobes_spectrum.glsl)
                        }
                    }
                }
                reporter.progress(task, (k + 1.0) / grid.wSamples());
            }
        }
        double seconds = (System.nanoTime() - start) * 1e-9;
        if (shortCells > 0) {
            reporter.warn(ShortPixels.warning(shortCells, grid.texels(), "cells of the table", "this GL",
                    "a patch of fewer texels, or a GPU, bakes them whole"));
        }
        BakedTable table = new BakedTable(grid, rgb, precision, seconds, tabulated, shortCells);
        reporter.info(String.format(Locale.ROOT, "baked %s in %.1f s", table.describe(), seconds));
        return table;
    }

    /** The cells whose lobes loops the GL that baked the table ended early (0 for a whole table). */
    public long shortCells() {
        return shortCells;
    }

    /** The method whose spectrum the samples hold. */
    public Variant tabulated() {
        return tabulated;
    }

    /** Whether the samples are cell and light averages (of the lobes method), else point samples (of FLSS). */
    public boolean filtered() {
        return tabulated.filtersLight();
    }

    public BakedGrid grid() {
        return grid;
    }

    /** The table's float32 values, RGB = XYZ, u fastest, then v, then w (do not modify). */
    float[] values() {
        return rgb;
    }

    /**
     * A new texture of the running sums of the table's rows along u ({@link BakedDisc#rowSums}, worked out once) for
     * one GL context: float32 (a piece of a row is a difference of two sums), mip-mapped per w slice.
     */
    public FloatTexture3D rowSumsTexture() {
        float[] sums;
        synchronized (this) {
            if (rowSums == null) {
                rowSums = BakedDisc.rowSums(rgb, grid);
            }
            sums = rowSums;
        }
        return new FloatTexture3D(grid.uvSamples(), grid.uvSamples(), grid.wSamples(), sums,
                FloatTexture3D.Precision.FLOAT32, true);
    }

    /**
     * This (filtered) table spread by the disc of half-angle {@code halfAngleRad} ({@link DiscTable#of}), worked out
     * on first use per light size; the last two sizes' are kept.
     */
    public DiscTable discTable(double halfAngleRad) {
        return discTable(halfAngleRad, Reporter.SILENT);
    }

    /** As {@link #discTable(double)}, the work's progress on {@code reporter}. */
    public synchronized DiscTable discTable(double halfAngleRad, Reporter reporter) {
        DiscTable spread = discTables.get(halfAngleRad);
        if (spread == null) {
            spread = DiscTable.of(this, halfAngleRad, reporter);
            discTables.put(halfAngleRad, spread);
        }
        return spread;
    }

    /** Whether a surface drawn with {@code settings} reads this table spread by their disc ({@link DiscTable}). */
    public boolean spreadsDisc(BrdfSettings settings) {
        return filtered() && DiscTable.applies(settings, grid);
    }

    /**
     * Whether a surface drawn with {@code settings} finds what it reads ready: the spread by their disc worked out
     * where it reads one ({@link #spreadsDisc}), else at once.
     */
    public synchronized boolean spreadReady(BrdfSettings settings) {
        return !spreadsDisc(settings) || discTables.containsKey(settings.illumination().light().halfAngleRad());
    }

    /** Works out the spread a surface drawn with {@code settings} reads ({@link #spreadReady}), if any. */
    public void prepareSpread(BrdfSettings settings, Reporter reporter) {
        if (spreadsDisc(settings)) {
            discTable(settings.illumination().light().halfAngleRad(), reporter);
        }
    }

    /** A new texture of the table for one GL context (the host values are shared, not copied). */
    public FloatTexture3D texture() {
        return new FloatTexture3D(grid.uvSamples(), grid.uvSamples(), grid.wSamples(), rgb, precision, filtered());
    }

    /** XYZ of sample (i, j, k) = (u_i, v_j, w_k), float32 as baked. */
    public float[] xyzAt(int i, int j, int k) {
        int n = grid.uvSamples();
        int at = 3 * (i + n * (j + n * k));
        return new float[] {rgb[at], rgb[at + 1], rgb[at + 2]};
    }

    /** Nominal GPU memory of the table: texels x bytes per texel of its format. */
    public long gpuBytes() {
        long base = grid.bytes(precision.bytesPerTexel());
        return filtered() ? base * 4 / 3 : base; // mip levels per w slice
    }

    /** Host memory of the float32 copy kept for uploads: texels x 12 bytes. */
    public long hostBytes() {
        return 4L * rgb.length;
    }

    public double bakeSeconds() {
        return bakeSeconds;
    }

    public FloatTexture3D.Precision precision() {
        return precision;
    }

    /** One line: grid, format and memory. */
    public String describe() {
        return String.format(Locale.ROOT, "%d x %d x %d table (u, v, w) of %s, %s, %.1f MB on the GPU, %.1f MB on the host",
                grid.uvSamples(), grid.uvSamples(), grid.wSamples(), tabulated.spec()
                        + (filtered() ? ", cell- and light-averaged" : ""), precision, gpuBytes() / 1e6,
                hostBytes() / 1e6);
    }
}
