package diffract.bench;

import diffract.optics.illumination.IlluminationSettings;

import java.util.Locale;

/** Number formatting shared by the bench's CSV, keys and tables. */
final class Csv {
    private Csv() {
    }

    /** Integers without a decimal point, others with up to 6 significant digits; NaN as "nan". */
    static String number(double v) {
        if (Double.isNaN(v)) {
            return "nan";
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return String.format(Locale.ROOT, "%.6g", v).replaceAll("(\\.\\d*?)0+$", "$1").replaceAll("\\.$", "");
    }

    /**
     * Every illumination setting that changes a map, for cache keys: sigma_s, refractive index, the light's
     * diameter (and "disc" for a disc light: Gaussian keys stay as they were), the pixel filter and the Fresnel model.
     */
    static String illuminationKey(IlluminationSettings i) {
        return String.join("-", "c" + number(i.sigmaSpatialUm()), "n" + number(i.refractiveIndex()),
                "d" + number(i.light().angularDiameterDeg())
                + (i.light().isDisc() ? "disc" : ""), i.pixelFilter().label(), i.gain().label());
    }
}
