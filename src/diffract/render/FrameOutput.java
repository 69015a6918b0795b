package diffract.render;

import java.util.Map;

/**
 * What the pixels of a drawn frame hold. {@link #DISPLAY}: display values, tone mapped, clipped to [0, 1] and
 * sRGB-encoded, what a window shows and a PNG stores. {@link #LINEAR}: linear light, the linear sRGB radiance times
 * the exposure (and a stage's exposure stops), neither tone mapped nor clipped nor encoded, for a still kept as
 * floats (an OpenEXR file). The shaders tell the two apart by the define {@value #LINEAR_DEFINE}.
 */
public enum FrameOutput {
    DISPLAY,
    LINEAR;

    /** Compiles the diffraction, staging and ground shaders for linear output. */
    public static final String LINEAR_DEFINE = "LINEAR_OUTPUT";

    /** Adds this output's defines to a program's. */
    void addDefines(Map<String, String> defines) {
        if (this == LINEAR) {
            defines.put(LINEAR_DEFINE, "1");
        }
    }
}
