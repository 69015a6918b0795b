package diffract.optics;

/** What one BRDF-map pixel shows (docs/filtering.md). */
public enum PixelFilter {
    /** The BRDF at the pixel's centre direction, the thesis' way (aliases orders narrower than a pixel). */
    POINT,
    /** The average of the BRDF over the pixel's square in the projected (x, y) plane: the definition. */
    BOX
}
