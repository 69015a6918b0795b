package diffract.colour;

/**
 * The CIEDE2000 colour difference (CIE 142-2001; ISO/CIE 11664-6) with parametric factors kL = kC = kH = 1,
 * implemented step by step after G. Sharma, W. Wu, E. N. Dalal, "The CIEDE2000 color-difference formula:
 * implementation notes, supplementary test data, and mathematical observations", Color Research and
 * Application 30(1):21-30, 2005, following its three steps. Hue angles are in degrees, as in the paper.
 */
public final class Ciede2000 {
    private static final double POW25_7 = Math.pow(25, 7); // 25^7, in G and in R_C

    private Ciede2000() {
    }

    /** Delta E 2000 between two colours given as XYZ, converted to L*a*b* relative to {@code white}. */
    public static double deltaE(Xyz a, Xyz b, Xyz white) {
        return deltaE(Lab.fromXyz(a, white), Lab.fromXyz(b, white));
    }

    /** Delta E 2000 between two L*a*b* colours; symmetric, 0 for equal colours. */
    public static double deltaE(Lab lab1, Lab lab2) {
        // Step 1: a', C', h'.
        double c1 = Math.hypot(lab1.a(), lab1.b());
        double c2 = Math.hypot(lab2.a(), lab2.b());
        double cMean7 = Math.pow((c1 + c2) / 2, 7);
        double g = 0.5 * (1 - Math.sqrt(cMean7 / (cMean7 + POW25_7)));
        double a1p = (1 + g) * lab1.a();
        double a2p = (1 + g) * lab2.a();
        double c1p = Math.hypot(a1p, lab1.b());
        double c2p = Math.hypot(a2p, lab2.b());
        double h1p = hueDegrees(lab1.b(), a1p);
        double h2p = hueDegrees(lab2.b(), a2p);

        // Step 2: delta L', delta C', delta h', delta H'.
        double deltaLp = lab2.l() - lab1.l();
        double deltaCp = c2p - c1p;
        double deltahp = hueDifferenceDegrees(a1p, lab1.b(), a2p, lab2.b(), h1p, h2p, c1p * c2p);
        double deltaHp = 2 * Math.sqrt(c1p * c2p) * Math.sin(Math.toRadians(deltahp / 2));

        // Step 3: means, T, delta theta, R_C, weighting functions S_L, S_C, S_H, rotation R_T.
        double lMeanP = (lab1.l() + lab2.l()) / 2;
        double cMeanP = (c1p + c2p) / 2;
        double hMeanP = meanHueDegrees(h1p, h2p, deltahp, c1p * c2p);
        double t = 1
                - 0.17 * Math.cos(Math.toRadians(hMeanP - 30))
                + 0.24 * Math.cos(Math.toRadians(2 * hMeanP))
                + 0.32 * Math.cos(Math.toRadians(3 * hMeanP + 6))
                - 0.20 * Math.cos(Math.toRadians(4 * hMeanP - 63));
        double deltaTheta = 30 * Math.exp(-square((hMeanP - 275) / 25));
        double cMeanP7 = Math.pow(cMeanP, 7);
        double rc = 2 * Math.sqrt(cMeanP7 / (cMeanP7 + POW25_7));
        double lMinus50Sq = square(lMeanP - 50);
        double sl = 1 + 0.015 * lMinus50Sq / Math.sqrt(20 + lMinus50Sq);
        double sc = 1 + 0.045 * cMeanP;
        double sh = 1 + 0.015 * cMeanP * t;
        double rt = -Math.sin(Math.toRadians(2 * deltaTheta)) * rc;

        double dl = deltaLp / sl;
        double dc = deltaCp / sc;
        double dh = deltaHp / sh;
        return Math.sqrt(dl * dl + dc * dc + dh * dh + rt * dc * dh);
    }

    // h' = atan2(b, a') in [0, 360), and 0 when a' = b = 0.
    private static double hueDegrees(double b, double ap) {
        if (ap == 0 && b == 0) {
            return 0;
        }
        double h = Math.toDegrees(Math.atan2(b, ap));
        return h < 0 ? h + 360 : h;
    }

    /**
     * delta h' = h2' - h1', plus or minus 360 to bring it into [-180, 180]; 0 if either chroma is 0.
     * Computed as the signed angle between (a1', b1) and (a2', b2) rather than by subtracting two rounded hue
     * angles, so that the tie |h2' - h1'| = 180 (exactly opposite hues; Sharma's pairs 10 and 14 probe it, and
     * the formula is discontinuous there) is detected exactly: the cross product is then exactly 0. Sharma
     * takes the "|h2' - h1'| &lt;= 180" branch for the tie, i.e. no wrap: delta h' = +180 if h2' &gt; h1',
     * else -180.
     */
    private static double hueDifferenceDegrees(double a1p, double b1, double a2p, double b2,
            double h1p, double h2p, double chromaProduct) {
        if (chromaProduct == 0) {
            return 0;
        }
        double cross = a1p * b2 - b1 * a2p;
        double dot = a1p * a2p + b1 * b2;
        if (cross == 0 && dot < 0) {
            return h2p > h1p ? 180 : -180;
        }
        return Math.toDegrees(Math.atan2(cross, dot));
    }

    /**
     * The mean hue h-bar'. Written as h1' + delta h'/2, reduced to [0, 360), which equals (h1' + h2')/2
     * when |h1' - h2'| &lt;= 180 (ties included) and (h1' + h2' +- 360)/2 otherwise.
     * If either chroma is 0 it is h1' + h2', as the paper prescribes.
     */
    private static double meanHueDegrees(double h1p, double h2p, double deltahp, double chromaProduct) {
        if (chromaProduct == 0) {
            return h1p + h2p;
        }
        double mean = h1p + deltahp / 2;
        if (mean >= 360) {
            mean -= 360;
        } else if (mean < 0) {
            mean += 360;
        }
        return mean;
    }

    private static double square(double v) {
        return v * v;
    }
}
