package diffract.optics;

import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.Footprint;
import diffract.optics.illumination.IlluminationSettings;
import diffract.optics.illumination.LightSource;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.SpectralSettings;
import diffract.optics.settings.WavelengthSampling;
import diffract.util.DiskCache;
import diffract.util.Reporter;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The rigorous method's BRDF of one patch: for each light direction asked, the orders' efficiencies
 * ({@link RigorousOrders}, solved once per direction and kept) drawn by the filtered reference's lobes, under a disc
 * light by its disc average. The solve for a direction happens when a command prepares a map for it
 * ({@link DiffractionBrdf#prepare}, with progress) or at its first pixel.
 */
final class RigorousBrdf {
    /** Directions kept: a map asks for one, a scene for its lights. */
    private static final int KEPT = 16;

    private final RigorousPatch patch;
    private final BrdfSettings settings;
    private final DiskCache cache;
    private final Map<Direction, Drawing> drawings = new LinkedHashMap<>(KEPT, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Direction, Drawing> eldest) {
            return size() > KEPT;
        }
    };

    /** The orders of one direction and their drawing. */
    private record Drawing(RigorousOrders orders, FilteredReference filtered, DiscLightAverage disc) {
    }

    RigorousBrdf(RigorousPatch patch, BrdfSettings settings, DiskCache cache) {
        this.patch = patch;
        this.settings = settings;
        this.cache = cache;
    }

    /** Solves (or loads) the orders for light from {@code wi}, reporting progress. */
    synchronized void prepare(Direction wi, Reporter reporter) {
        drawing(wi, reporter);
    }

    private synchronized Drawing drawing(Direction wi, Reporter reporter) {
        Drawing d = drawings.get(wi);
        if (d != null) {
            return d;
        }
        RigorousOrders orders = RigorousOrders.of(patch, settings, wi, cache, reporter);
        FilteredReference filtered = new FilteredReference(orders, patch.field().widthUm(),
                patch.field().heightExtentUm(), settings.coherenceWindow(), settings.spectral());
        LightSource light = settings.illumination().light();
        DiscLightAverage disc = light.isDisc() ? new DiscLightAverage(filtered, light) : null;
        d = new Drawing(orders, filtered, disc);
        drawings.put(wi, d);
        return d;
    }

    private Drawing drawing(Direction wi) {
        return drawing(wi, Reporter.SILENT);
    }

    /** Pixel (column, row) of an S x S map averaged over its square (or at its centre), the light and the band. */
    Xyz mapPixel(Direction wi, int column, int row, int size) {
        Drawing d = drawing(wi);
        if (d.disc != null) {
            return d.disc.mapPixel(wi, column, row, size);
        }
        IlluminationSettings illumination = settings.illumination();
        if (illumination.pixelFilter() != PixelFilter.BOX) {
            double x = BrdfMap.xOf(column, size);
            double y = BrdfMap.yOf(row, size);
            return x * x + y * y >= 1 ? new Xyz(0, 0, 0) : xyz(wi, Direction.fromProjected(x, y));
        }
        return d.filtered.mapPixel(wi, illumination.light().uvCovariance(wi), column, row, size);
    }

    /**
     * The direction omega_r itself (no pixel), over the light and the band; under a point light summed over the
     * reference's wavelengths (1 nm) as the reference's point-sampled map is, else integrated as its filtered one.
     */
    Xyz xyz(Direction wi, Direction wr) {
        Drawing d = drawing(wi);
        if (d.disc != null) {
            return d.disc.at(wi, wr);
        }
        if (!settings.illumination().filters()) {
            SpectralSettings spectral = settings.spectral();
            WavelengthSampling.Quadrature q = WavelengthSampling.uniform(spectral.lambdaMinNm(), spectral.lambdaMaxNm(),
                    SpectralSettings.REFERENCE_STEP_NM, spectral.normalisation()).quadratureFor(0, 0);
            double sigmaF = settings.coherenceWindow().sigmaFrequencyPerUm();
            double[] power = new double[q.lambdasNm().length];
            for (int j = 0; j < power.length; j++) {
                power[j] = d.orders.relative(wi, wr, q.lambdasNm()[j], sigmaF);
            }
            return diffract.colour.SpectralIntegrator.weightedSum(q.xyzWeights(), power);
        }
        double[] v = d.filtered.at(wi, wr, Footprint.POINT.plus(settings.illumination().light().uvCovariance(wi)));
        return new Xyz(v[0], v[1], v[2]);
    }

    /** The relative BRDF at one wavelength, at the direction itself. */
    double relative(Direction wi, Direction wr, double lambdaNm) {
        return drawing(wi).orders.relative(wi, wr, lambdaNm, settings.coherenceWindow().sigmaFrequencyPerUm());
    }
}
