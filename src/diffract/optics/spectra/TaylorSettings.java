package diffract.optics.spectra;

import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;

/**
 * The Taylor approximation of exp(i k w h) (001 sec. 3.3.3; 003 Algorithm 3): how many orders, where each lookup
 * may stop early, and which expansion.
 *
 * @param highestOrder N, the last order summed (N + 1 terms); at most {@link #MAX_HIGHEST_ORDER}
 * @param tolerance    each lookup's loop stops at the first order n whose Lagrange remainder x^(n+1) e^x / (n+1)!
 *                     (x = k |w| max|h| of that lookup) is at most this; 0 = always N (the thesis' behaviour)
 * @param expansion    the series around 0, the phase-centred expansion, or the choice between them per patch
 */
public record TaylorSettings(int highestOrder, double tolerance, TaylorExpansion expansion) {
    /**
     * The one limit on N for every command and scene. Float32 sums of tall patches' terms overflow long before it
     * (docs/guide/limits.md); patches that would need more use the phase-centred expansion, whose orders stay small.
     */
    public static final int MAX_HIGHEST_ORDER = 100;

    public TaylorSettings {
        if (highestOrder < 0 || highestOrder > MAX_HIGHEST_ORDER) {
            throw new InvalidSettingException(Quantity.HIGHEST_ORDER, Quantity.HIGHEST_ORDER.words()
                    + " must be in 0.." + MAX_HIGHEST_ORDER + ", got " + highestOrder);
        }
        if (!(tolerance >= 0 && tolerance < 1)) {
            throw new InvalidSettingException(Quantity.TAYLOR_TOLERANCE, Quantity.TAYLOR_TOLERANCE.words()
                    + " must be in [0, 1) (0 = always N), got " + tolerance);
        }
        if (expansion == null) {
            throw new IllegalArgumentException("the Taylor expansion is required (AUTO by default)");
        }
    }

    /** 30 terms, no early stop, the automatic expansion. */
    public static TaylorSettings thesis() {
        return new TaylorSettings(30, 0, TaylorExpansion.AUTO);
    }

    /**
     * The highest order any lookup can use (only these terms need to be uploaded): N, or with a tolerance the
     * order at which the bound for the largest phase x = (2 pi / lambda_min) 2 max|h| (the worst lookup) meets
     * it, if that is below N. Every lookup's own stop order is at most this, since the bound grows with x.
     */
    public int highestOrderNeeded(double lambdaMinNm, double maxAbsHeightUm) {
        if (tolerance == 0) {
            return highestOrder;
        }
        double x = TaylorBound.maxPhase(lambdaMinNm, maxAbsHeightUm);
        return Math.min(highestOrder, TaylorBound.stopOrder(x, tolerance, highestOrder));
    }
}
