package diffract.app.options;

import diffract.optics.settings.Quantity;

import java.util.EnumMap;
import java.util.Map;

/**
 * The option that gives each {@link Quantity}: a message about a quantity (from the settings, a reader or the
 * precompute) is shown with the option the user types, e.g. {@code --terms: the highest Taylor order N must be in
 * 0..100, got 150}. Scene files name the same quantities by their keys ({@code SceneFile.MATERIAL_KEYS}).
 */
public final class OptionNames {
    private static final Map<Quantity, String> FLAGS = new EnumMap<>(Quantity.class);

    static {
        FLAGS.put(Quantity.VARIANT, "--variant");
        FLAGS.put(Quantity.HIGHEST_ORDER, "--terms");
        FLAGS.put(Quantity.ORDER_TOLERANCE, "--tolerance");
        FLAGS.put(Quantity.TAYLOR_TOLERANCE, "--taylor-tolerance");
        FLAGS.put(Quantity.EXPANSION, "--expansion");
        FLAGS.put(Quantity.WINDOW_RADIUS, "--window-radius");
        FLAGS.put(Quantity.PQ_REPLICAS, "--pq-replicas");
        FLAGS.put(Quantity.WINDOW_PLACEMENT, "--window");
        FLAGS.put(Quantity.SCAN_TILING, "--skin-um-per-texcoord");
        FLAGS.put(Quantity.LAMBDA_MIN, "--lambda-min");
        FLAGS.put(Quantity.LAMBDA_MAX, "--lambda-max");
        FLAGS.put(Quantity.LAMBDA_STEP, "--lambda-step");
        FLAGS.put(Quantity.MONOCHROMATIC_LAMBDA, "--lambda");
        FLAGS.put(Quantity.COHERENCE_LENGTH, "--coherence-length");
        FLAGS.put(Quantity.REFRACTIVE_INDEX, "--refractive-index");
        FLAGS.put(Quantity.HARMONICS, "--harmonics");
        FLAGS.put(Quantity.LAYERS, "--layers");
        FLAGS.put(Quantity.POLARISATION, "--polarisation");
        FLAGS.put(Quantity.ORDERS, "--orders");
        FLAGS.put(Quantity.LIGHT_SIZE, "--light-size-deg");
        FLAGS.put(Quantity.LIGHT_PROFILE, "--light-profile");
        FLAGS.put(Quantity.GAIN, "--gain");
        FLAGS.put(Quantity.PIXEL_FILTER, "--pixel-filter");
        FLAGS.put(Quantity.LOBE_QUADRATURE, "--lobe-quadrature");
        FLAGS.put(Quantity.TERM_FORMAT, "--texture-format");
        FLAGS.put(Quantity.BAKED_SAMPLES, "--baked-samples");
        FLAGS.put(Quantity.MAX_HEIGHT, "--max-height");
        FLAGS.put(Quantity.PIXEL_SIZE, "--pixel-size");
        FLAGS.put(Quantity.CHANNEL, "--channel");
        FLAGS.put(Quantity.TERMS_HEIGHT_UNIT, "--terms-height-unit");
    }

    private OptionNames() {
    }

    /** The option of a quantity (every quantity has one). */
    public static String of(Quantity quantity) {
        String flag = FLAGS.get(quantity);
        if (flag == null) {
            throw new IllegalStateException("no option gives " + quantity);
        }
        return flag;
    }
}
