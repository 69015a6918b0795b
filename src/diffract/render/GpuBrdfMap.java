package diffract.render;

import diffract.jrtr.scenegraph.Camera;
import diffract.jrtr.scenegraph.Frustum;
import diffract.jrtr.contexts.GLInfo;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.OffscreenTarget;
import diffract.jrtr.Renderer;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.LightPolicy;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.settings.Quantity;
import diffract.optics.TaylorEvaluation;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;
import diffract.util.UserInputException;

/**
 * BRDF maps on the GPU, with the pixel convention of {@link diffract.optics.BrdfMap}: pixel (i, j) of an S x S map
 * (j from the top) shows omega_r = (x, y, sqrt(1 - x^2 - y^2)), x = 2 (i + 0.5) / S - 1, y = 1 - 2 (j + 0.5) / S,
 * black outside the unit disk. Rendered offscreen into an RGBA32F target and read back, so the result goes through
 * the same colour pipeline ({@link diffract.colour.ColourPath}) as the CPU's map. Holds a hidden GL context: close it.
 * Not thread-safe.
 */
public final class GpuBrdfMap implements AutoCloseable {
    private final BrdfSettings settings;
    private final DiffractionTextures textures;
    private final ShapeNode quad;
    private final OffscreenTarget target;
    private Material xyzMaterial;
    private Material monochromaticMaterial;
    private int truncatedPixels;
    private boolean[] truncated = new boolean[0];

    /**
     * The map of the thesis' series over these terms, stored in the settings' term format.
     *
     * @param terms the precomputed float32 Taylor terms (at least N)
     * @throws UserInputException for the reference variant, or when no GL context can be opened
     */
    public GpuBrdfMap(TaylorTerms terms, BrdfSettings settings) {
        this(TaylorEvaluation.plain(terms), settings, Reporter.SILENT);
    }

    /** The phase-centred expansion: the same maps for patches too tall for the thesis' series. */
    public GpuBrdfMap(PhaseCentredTerms terms, BrdfSettings settings) {
        this(TaylorEvaluation.phaseCentred(terms), settings, Reporter.SILENT);
    }

    /**
     * The map on the path {@link TaylorEvaluation#choose} picked for a patch; a baked table is baked (or loaded from
     * the disk cache) for this map alone, with progress on {@code reporter}.
     */
    public GpuBrdfMap(TaylorEvaluation evaluation, BrdfSettings settings, Reporter reporter) {
        this(evaluation, settings, new BakedTables(), reporter);
    }

    /** As above, a baked table from {@code tables} (a pipeline's), baked there first if it is not at hand. */
    public GpuBrdfMap(TaylorEvaluation evaluation, BrdfSettings settings, BakedTables tables, Reporter reporter) {
        this(DiffractionTextures.of(evaluation, requireGpuVariant(settings), tables, reporter), settings);
    }

    private static BrdfSettings requireGpuVariant(BrdfSettings settings) {
        if (!settings.variant().runsOnGpu()) {
            throw new InvalidSettingException(Quantity.VARIANT, DiffractionShaders.cpuOnly(settings.variant()));
        }
        return LightPolicy.of(settings).requireAccepted();
    }

    private GpuBrdfMap(DiffractionTextures textures, BrdfSettings settings) {
        this.settings = settings;
        this.textures = textures;
        this.xyzMaterial = DiffractionMaterials.brdfMap(textures, settings, false);
        this.quad = new ShapeNode(Shapes.fullScreenQuad(), xyzMaterial);
        this.target = new OffscreenTarget(new Renderer(new Group("brdf map").add(quad), new Camera(), new Frustum()));
    }

    /**
     * The local window's centre on the scan (um) and its footprint's covariance (um^2) for the maps that follow
     * ({@link diffract.optics.windows.WindowPlacement#LOCAL}: a map has no surface point; until placed, the window sits
     * at the scan's origin with no footprint); nothing for other placements.
     */
    public GpuBrdfMap placeWindow(double centreXUm, double centreYUm,
            diffract.optics.numerics.Covariance2 footprintUm2) {
        DiffractionMaterials.placeMapWindow(xyzMaterial, settings, centreXUm, centreYUm, footprintUm2);
        return this;
    }

    /** CIE XYZ per pixel (D65 white at Y = 1), 3 floats per pixel, rows from the top, as BrdfMap.xyz. */
    public float[] xyz(Direction wi, int size) {
        use(xyzMaterial, wi, size);
        float[] rgba = target.renderRgba(size, size);
        truncatedPixels = 0;
        truncated = new boolean[size * size];
        for (int p = 0; p < size * size; p++) {
            double x = BrdfMap.xOf(p % size, size);
            double y = BrdfMap.yOf(p / size, size);
            if (rgba[4 * p + 3] == 0 && x * x + y * y < 1) {
                truncatedPixels++; // the lobes shader's loops were ended early here (lobes_spectrum.glsl)
                truncated[p] = true;
            }
        }
        return OffscreenTarget.dropAlpha(rgba);
    }

    /**
     * Pixels of the last {@link #xyz} map where the GL ended the lobes shader's loops early and lobes were left out
     * (Mesa's llvmpipe ends a SIMD group's loops after 65535 iterations; the shader notices its loops did not finish).
     */
    public int truncatedPixels() {
        return truncatedPixels;
    }

    /** Whether pixel p (row-major from the top) of the last {@link #xyz} map was left short. */
    public boolean truncatedAt(int p) {
        return truncated[p];
    }

    /** The relative BRDF at {@code lambdaNm} per pixel, as BrdfMap.monochromatic. */
    public float[] monochromatic(Direction wi, double lambdaNm, int size) {
        requireSpectral();
        useMonochromatic(wi, lambdaNm, size);
        float[] rgba = target.renderRgba(size, size);
        float[] rho = new float[size * size];
        for (int p = 0; p < rho.length; p++) {
            rho[p] = rgba[4 * p];
        }
        return rho;
    }

    /**
     * Median GPU time (GL timer queries) of one S x S colour map, over {@code frames} >= 10 frames after
     * {@code warmupFrames} unmeasured ones (compilation and uploads happen in warm-up).
     */
    public double medianMsPerFrame(Direction wi, int size, int warmupFrames, int frames) {
        use(xyzMaterial, wi, size);
        return target.measureMedianMs(size, size, warmupFrames, frames);
    }

    /** As {@link #medianMsPerFrame} for the monochromatic map at {@code lambdaNm}. */
    public double medianMsPerFrameMonochromatic(Direction wi, double lambdaNm, int size, int warmupFrames, int frames) {
        requireSpectral();
        useMonochromatic(wi, lambdaNm, size);
        return target.measureMedianMs(size, size, warmupFrames, frames);
    }

    /** The baked table (BAKED only; null otherwise): its grid, memory and bake time. */
    public BakedTable bakedTable() {
        return textures.baked();
    }

    /** The baked table holds colour (XYZ), not the BRDF at one wavelength. */
    private void requireSpectral() {
        if (settings.variant().drawsTable()) {
            throw new InvalidSettingException(Quantity.MONOCHROMATIC_LAMBDA, BAKED_HAS_NO_MONOCHROMATIC);
        }
    }

    /** Why a monochromatic map of the baked variant cannot be made. */
    public static final String BAKED_HAS_NO_MONOCHROMATIC =
            "the baked variant tabulates colour (XYZ), not single wavelengths: use flss for a monochromatic map";

    /** The GL driver's version and renderer strings. */
    public GLInfo info() {
        return target.info();
    }

    private void useMonochromatic(Direction wi, double lambdaNm, int size) {
        if (monochromaticMaterial == null) {
            monochromaticMaterial = DiffractionMaterials.brdfMap(textures, settings, true);
        }
        use(monochromaticMaterial, wi, size);
        monochromaticMaterial.setFloat("lambdaNm", (float) lambdaNm);
    }

    private void use(Material material, Direction wi, int size) {
        if (size < 1) {
            throw new IllegalArgumentException("map size must be >= 1, got " + size);
        }
        // the whole viewport is the map (a window centres a smaller one)
        DiffractionMaterials.setLight(material, wi, settings).setFloat("mapSizePx", size).setVec2("mapOriginPx", 0, 0);
        quad.setMaterial(material);
    }

    @Override
    public void close() {
        target.close();
    }
}
