package diffract.util;

import java.util.Arrays;

/**
 * The lists a measurement run on request takes from system properties, comma-separated
 * ({@code -Ddiffract.measure.discs=2,10}), so that a part of a long measurement can be run alone.
 */
public final class MeasureProperties {
    private MeasureProperties() {
    }

    /** The numbers of {@code property}, or of {@code fallback} where it is not set. */
    public static double[] doubles(String property, String fallback) {
        return Arrays.stream(System.getProperty(property, fallback).split(",")).mapToDouble(Double::parseDouble)
                .toArray();
    }

    /** The whole numbers of {@code property}, or of {@code fallback} where it is not set. */
    public static int[] ints(String property, String fallback) {
        return Arrays.stream(System.getProperty(property, fallback).split(",")).mapToInt(Integer::parseInt).toArray();
    }
}
