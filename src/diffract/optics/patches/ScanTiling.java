package diffract.optics.patches;

import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;

/**
 * How a scan lies on a mesh's skin for the local window ({@code WindowPlacement.LOCAL}): the
 * micrometres of skin one unit of the mesh's texture coordinates spans along u and along v. The scan's periodic patch
 * then repeats every L_x / umPerTexcoordU along u, and a surface point at texture coordinates (u, v) sees the window
 * centred at x0 = (u umPerTexcoordU, v umPerTexcoordV) um on the scan (x along its columns, y along its rows), or, with
 * {@code columnsAlongV}, at x0 = (v umPerTexcoordV, u umPerTexcoordU): for meshes whose patch x axis (the tangent)
 * runs along v, as the snake's with its ridges along the body.
 *
 * @param umPerTexcoordU micrometres of skin per unit of u (0: not given)
 * @param umPerTexcoordV micrometres of skin per unit of v (0: not given)
 * @param columnsAlongV  the scan's columns (its x axis) run along v instead of u
 */
public record ScanTiling(double umPerTexcoordU, double umPerTexcoordV, boolean columnsAlongV) {
    /** Not given: the averaged and fixed windows need none. */
    public static final ScanTiling NONE = new ScanTiling(0, 0, false);
    /** The largest tiling: a unit of texture coordinates as 10 m of skin. */
    public static final double MAX_UM_PER_TEXCOORD = 1e7;

    public ScanTiling {
        if (!(umPerTexcoordU >= 0 && umPerTexcoordU <= MAX_UM_PER_TEXCOORD && umPerTexcoordV >= 0
                && umPerTexcoordV <= MAX_UM_PER_TEXCOORD)) {
            throw new InvalidSettingException(Quantity.SCAN_TILING, Quantity.SCAN_TILING.words()
                    + " must be in [0, " + (long) MAX_UM_PER_TEXCOORD + "] um per unit, got " + umPerTexcoordU
                    + " and " + umPerTexcoordV);
        }
    }

    /** Whether both axes are given (above 0). */
    public boolean given() {
        return umPerTexcoordU > 0 && umPerTexcoordV > 0;
    }

    /** x0 on the scan, um (x along its columns, y along its rows), of the surface point at texture coordinates (u, v). */
    public double[] centreUm(double u, double v) {
        double alongU = u * umPerTexcoordU;
        double alongV = v * umPerTexcoordV;
        return columnsAlongV ? new double[] {alongV, alongU} : new double[] {alongU, alongV};
    }
}
