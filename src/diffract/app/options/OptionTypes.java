package diffract.app.options;

import diffract.optics.settings.GainModel;
import diffract.optics.patches.Levelling;
import diffract.optics.settings.LightProfile;
import diffract.optics.LobeQuadrature;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.settings.PixelFilter;
import diffract.optics.Variant;
import diffract.optics.windows.WindowPlacement;
import diffract.precompute.ThesisFormat;
import diffract.scene.Scene;
import diffract.util.UserInputException;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;

/**
 * The value types of the options that are more than a number or an enum, each with its picocli converter (a bad
 * value is picocli's one-line "Invalid value for option" with the reason), and the completion candidates of the
 * options whose values are names.
 */
public final class OptionTypes {
    private OptionTypes() {
    }

    /** {@code --variant}: a variant, or {@code auto} (null variant), the cheapest measured one for an accuracy target. */
    record VariantChoice(Variant variant) {
        static final String AUTO = "auto";

        boolean auto() {
            return variant == null;
        }

        public static final class Converter implements ITypeConverter<VariantChoice> {
            @Override
            public VariantChoice convert(String text) {
                if (text.trim().equalsIgnoreCase(AUTO)) {
                    return new VariantChoice(null);
                }
                try {
                    return new VariantChoice(Variant.parse(text));
                } catch (UserInputException e) {
                    // an unknown name: the registry's list, with auto beside it
                    String message = e.getMessage();
                    throw new TypeConversionException(message.startsWith("unknown variant")
                            ? message.replaceFirst(" or ([a-z0-9-]+)$", ", $1 or auto") : message);
                }
            }
        }

        /** reference, flss, nmm, pq, baked, auto. */
        static final class Candidates implements Iterable<String> {
            @Override
            public Iterator<String> iterator() {
                List<String> names = new ArrayList<>();
                for (Variant v : Variant.values()) {
                    names.add(v.label());
                }
                names.add(AUTO);
                return names.iterator();
            }
        }
    }

    /** {@code --window-radius R|auto}: a fixed radius, or (null) the radius per axis from sigma_f. */
    record WindowRadius(Integer radius) {
        public boolean automatic() {
            return radius == null;
        }

        public static final class Converter implements ITypeConverter<WindowRadius> {
            @Override
            public WindowRadius convert(String text) {
                if (text.trim().equalsIgnoreCase("auto")) {
                    return new WindowRadius(null);
                }
                return new WindowRadius(whole(text, "a whole number of texels or auto"));
            }
        }
    }

    /** {@code --harmonics M|auto}: the rigorous method's highest harmonic, or (0) chosen per wavelength. */
    record Harmonics(int maxOrder) {
        public static final class Converter implements ITypeConverter<Harmonics> {
            @Override
            public Harmonics convert(String text) {
                if (text.trim().equalsIgnoreCase("auto")) {
                    return new Harmonics(0);
                }
                return new Harmonics(whole(text, "a whole number of harmonics or auto"));
            }
        }
    }

    /** {@code --refractive-index N[+Ki]}: a complex index, n alone for a lossless material. */
    static final class ComplexIndexConverter implements ITypeConverter<diffract.optics.rigorous.ComplexIndex> {
        @Override
        public diffract.optics.rigorous.ComplexIndex convert(String text) {
            try {
                return diffract.optics.rigorous.ComplexIndex.parse(text);
            } catch (IllegalArgumentException e) {
                throw new picocli.CommandLine.TypeConversionException("'" + text + "' is not a refractive index: write n "
                        + "or n+ki, e.g. 1.56 or 1.56+0.03i");
            }
        }
    }

    /** {@code --exposure E|auto}: a positive factor, or (null) the brightest diffracted pixel mapped to 1. */
    public record Exposure(Double factor) {
        public boolean automatic() {
            return factor == null;
        }

        public static final class Converter implements ITypeConverter<Exposure> {
            @Override
            public Exposure convert(String text) {
                if (text.trim().equalsIgnoreCase("auto")) {
                    return new Exposure(null);
                }
                return new Exposure(positive(text, "a positive number or auto"));
            }
        }
    }

    /**
     * {@code --size WxH} (or {@code S} for a square), {@value #MIN_PX}..{@value #MAX_PX} pixels per side: the one
     * form and range of every command's picture size (a BRDF map takes squares only, {@link Side}).
     */
    public record ImageSize(int width, int height) {
        static final int MIN_PX = Scene.ImageSize.MIN_PX;
        static final int MAX_PX = Scene.ImageSize.MAX_PX;

        /** The side of a square size (S or SxS): a BRDF map, whose pixels are directions over the unit disk. */
        public static final class Side implements ITypeConverter<Integer> {
            @Override
            public Integer convert(String text) {
                ImageSize size = new Converter().convert(text);
                if (size.width() != size.height()) {
                    throw new TypeConversionException("a BRDF map is square: give one side, S or SxS, got '" + text
                            + "'");
                }
                return size.width();
            }
        }

        public static final class Converter implements ITypeConverter<ImageSize> {
            @Override
            public ImageSize convert(String text) {
                String[] parts = text.toLowerCase(Locale.ROOT).split("x", -1);
                if (parts.length <= 2) {
                    int w = whole(parts[0], "WxH or S");
                    int h = parts.length == 1 ? w : whole(parts[1], "WxH or S");
                    if (w >= MIN_PX && h >= MIN_PX && w <= MAX_PX && h <= MAX_PX) {
                        return new ImageSize(w, h);
                    }
                }
                throw new TypeConversionException("must be WxH (or S) with " + MIN_PX + ".." + MAX_PX
                        + " pixels per side, got '" + text + "'");
            }
        }
    }

    /** {@code --baked-samples UV,W}: the baked table's samples (0 = automatic). */
    public record BakedSamples(int uv, int w) {
        public static final class Converter implements ITypeConverter<BakedSamples> {
            @Override
            public BakedSamples convert(String text) {
                String[] parts = text.split(",", -1);
                if (parts.length != 2) {
                    throw new TypeConversionException("must be UV,W (whole numbers, 0 = automatic), got '" + text + "'");
                }
                return new BakedSamples(whole(parts[0], "UV,W"), whole(parts[1], "UV,W"));
            }
        }
    }

    /**
     * {@code --lobe-quadrature K=V[,K=V]}: the knobs of {@link LobeQuadrature} given, by their record names; the
     * quadrature checks the values when applied.
     */
    record LobeQuadratureChange(java.util.Map<String, Double> values) {
        LobeQuadrature applyTo(LobeQuadrature q) {
            return q.withKnobs(values);
        }

        public static final class Converter implements ITypeConverter<LobeQuadratureChange> {
            @Override
            public LobeQuadratureChange convert(String text) {
                java.util.Map<String, Double> values = new java.util.LinkedHashMap<>();
                for (String part : text.split(",", -1)) {
                    String[] kv = part.split("=", -1);
                    String key = kv[0].trim();
                    if (kv.length != 2 || !LobeQuadrature.KNOBS.contains(key)) {
                        throw new TypeConversionException("must be K=V pairs with K one of "
                                + String.join(", ", LobeQuadrature.KNOBS)
                                + ", got '" + part.trim() + "'");
                    }
                    try {
                        values.put(key, Double.parseDouble(kv[1].trim()));
                    } catch (NumberFormatException e) {
                        throw new TypeConversionException(key + " must be a number, got '" + kv[1].trim() + "'");
                    }
                }
                return new LobeQuadratureChange(java.util.Map.copyOf(values));
            }
        }
    }

    /** peak, energy. */
    static final class NormalisationNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return java.util.Arrays.stream(diffract.colour.MirrorNormalisation.values())
                    .map(diffract.colour.MirrorNormalisation::key).iterator();
        }
    }

    /** rayleigh-rice, stam, thesis. */
    static final class GainNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return java.util.Arrays.stream(GainModel.values()).map(GainModel::label).iterator();
        }
    }

    /** {@code --gain G}: a {@link GainModel} by its label ("physical" still names stam). */
    static final class GainConverter implements ITypeConverter<GainModel> {
        @Override
        public GainModel convert(String text) {
            try {
                return GainModel.parse(text);
            } catch (diffract.optics.settings.InvalidSettingException e) {
                throw new picocli.CommandLine.TypeConversionException("'" + text + "' is not a gain model: use "
                        + String.join(", ", new GainNames()));
            }
        }
    }

    /** scalar, rigorous. */
    static final class OrderWeightsNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return java.util.Arrays.stream(diffract.optics.settings.OrderWeights.values())
                    .map(diffract.optics.settings.OrderWeights::label).iterator();
        }
    }

    /** unpolarised, s, p. */
    static final class PolarisationNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return java.util.Arrays.stream(diffract.optics.settings.Polarisation.values())
                    .map(diffract.optics.settings.Polarisation::label).iterator();
        }
    }

    /** disc, gaussian. */
    static final class LightProfileNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return java.util.Arrays.stream(LightProfile.values()).map(LightProfile::label).iterator();
        }
    }

    /** box, point. */
    static final class WindowPlacementNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return List.of(WindowPlacement.AVERAGED.label(), WindowPlacement.FIXED.label(), WindowPlacement.LOCAL.label())
                    .iterator();
        }
    }

    static final class PixelFilterNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return List.of(PixelFilter.BOX.label(), PixelFilter.POINT.label()).iterator();
        }
    }

    /** {@code --level plane|rows|none}. */
    public static final class LevellingNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return java.util.Arrays.stream(Levelling.values()).map(Levelling::label).iterator();
        }

        public static final class Converter implements ITypeConverter<Levelling> {
            @Override
            public Levelling convert(String text) {
                Levelling levelling = Levelling.fromLabel(text.trim());
                if (levelling == null) {
                    throw new TypeConversionException("must be plane, rows or none, got '" + text + "'");
                }
                return levelling;
            }
        }
    }

    /** {@code --tangent X,Y,Z}: a non-zero world direction. */
    public record Vector3(double x, double y, double z) {
        public static final class Converter implements ITypeConverter<Vector3> {
            @Override
            public Vector3 convert(String text) {
                String[] parts = text.split(",", -1);
                if (parts.length == 3) {
                    try {
                        Vector3 v = new Vector3(Double.parseDouble(parts[0].trim()), Double.parseDouble(parts[1].trim()),
                                Double.parseDouble(parts[2].trim()));
                        if (Double.isFinite(v.x + v.y + v.z) && v.x * v.x + v.y * v.y + v.z * v.z > 1e-12) {
                            return v;
                        }
                    } catch (NumberFormatException e) {
                        // the message below says what is expected
                    }
                }
                throw new TypeConversionException("must be a non-zero vector X,Y,Z, got '" + text + "'");
            }
        }
    }

    /** {@code --terms-height-unit auto|m|um}. */
    public static final class HeightUnitConverter implements ITypeConverter<ThesisFormat.HeightUnit> {
        @Override
        public ThesisFormat.HeightUnit convert(String text) {
            try {
                return ThesisFormat.HeightUnit.parse(text);
            } catch (UserInputException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }

    /** The named patches of the {@link PatchCatalogue}. */
    public static final class PatchNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return PatchCatalogue.names().iterator();
        }
    }

    /** The shapes a command line can name (an OBJ file needs a scene). */
    public static final class ShapeNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            List<String> names = new ArrayList<>();
            for (Scene.ShapeKind kind : Scene.ShapeKind.values()) {
                if (kind != Scene.ShapeKind.OBJ) {
                    names.add(kind.sceneName());
                }
            }
            return names.iterator();
        }
    }

    private static int whole(String text, String expected) {
        try {
            return Integer.parseInt(text.trim());
        } catch (NumberFormatException e) {
            throw new TypeConversionException("must be " + expected + ", got '" + text + "'");
        }
    }

    private static double positive(String text, String expected) {
        try {
            double v = Double.parseDouble(text.trim());
            if (v > 0 && Double.isFinite(v)) {
                return v;
            }
        } catch (NumberFormatException e) {
            // the message below says what is expected
        }
        throw new TypeConversionException("must be " + expected + ", got '" + text + "'");
    }
}
