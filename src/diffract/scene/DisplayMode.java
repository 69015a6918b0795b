package diffract.scene;

/** What the window shows. */
public enum DisplayMode {
    /** The shape with the diffraction surface material, seen from the orbit camera. */
    SURFACE,
    /** The BRDF map of the patch for the current light (theta_i, phi_i in the tangent frame), over all views. */
    BRDF_MAP
}
