package diffract.optics.rigorous;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A material's complex refractive index n + i k (k &gt;= 0 absorbs, with fields varying as exp(-i omega t)), and its
 * relative permittivity epsilon = (n + i k)^2.
 *
 * @param n the real part (the phase index), &gt; 0
 * @param k the extinction coefficient, &gt;= 0
 */
public record ComplexIndex(double n, double k) {
    /** Lossless keratin, the stuff of snake scales: n = 1.56 (Leertouwer, Wilts and Stavenga 2011, beta-keratin). */
    public static final ComplexIndex KERATIN = new ComplexIndex(1.56, 0);
    /** Air. */
    public static final ComplexIndex AIR = new ComplexIndex(1, 0);

    public ComplexIndex {
        if (!(n > 0) || !Double.isFinite(n) || !(k >= 0) || !Double.isFinite(k)) {
            throw new IllegalArgumentException("a refractive index needs n > 0 and k >= 0, got " + n + " + " + k + "i");
        }
    }

    /** Re epsilon = n^2 - k^2. */
    public double permittivityRe() {
        return n * n - k * k;
    }

    /** Im epsilon = 2 n k. */
    public double permittivityIm() {
        return 2 * n * k;
    }

    /** Whether it absorbs (k &gt; 0). */
    public boolean absorbs() {
        return k > 0;
    }

    /** The power reflectance of a flat interface from air at normal incidence, |(1 - N) / (1 + N)|^2. */
    public double normalReflectance() {
        double dr = 1 - n;
        double sr = 1 + n;
        return (dr * dr + k * k) / (sr * sr + k * k);
    }

    private static final Pattern TEXT = Pattern.compile(
            "\\s*([0-9]*\\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\\s*(?:\\+\\s*([0-9]*\\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\\s*[ij])?\\s*");

    /** "1.56" or "1.56+0.02i" (j too), as the command line and scene files write it. */
    public static ComplexIndex parse(String text) {
        Matcher m = TEXT.matcher(text);
        if (!m.matches()) {
            throw new IllegalArgumentException("a complex refractive index is written n or n+ki (1.56, 1.56+0.02i), got '"
                    + text + "'");
        }
        return new ComplexIndex(Double.parseDouble(m.group(1)), m.group(2) == null ? 0 : Double.parseDouble(m.group(2)));
    }

    /** "1.56" or "1.56+0.02i": what {@link #parse} reads. */
    @Override
    public String toString() {
        String real = number(n);
        return k == 0 ? real : real + "+" + number(k) + "i";
    }

    private static String number(double x) {
        String s = String.format(Locale.ROOT, "%.6g", x);
        if (s.contains("e") || !s.contains(".")) {
            return s;
        }
        s = s.replaceAll("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }
}
