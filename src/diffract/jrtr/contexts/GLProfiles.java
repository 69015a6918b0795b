package diffract.jrtr.contexts;

import com.jogamp.opengl.GLCapabilities;
import com.jogamp.opengl.GLException;
import com.jogamp.opengl.GLProfile;

/** Picks the OpenGL profile the engine asks JOGL for: the newest core profile (3.3 core or newer needed). */
public final class GLProfiles {
    private GLProfiles() {
    }

    /**
     * The newest core profile the platform offers, or JOGL's default when there is none (the render context
     * then reports which version was found). Throws {@link diffract.util.UserInputException} with the display
     * hint when no display is available.
     */
    public static GLProfile coreProfile() {
        DisplayCheck.requireDisplay();
        try {
            return GLProfile.getMaxProgrammableCore(true);
        } catch (GLException noCoreProfile) {
            return GLProfile.getDefault();
        }
    }

    /** RGBA8 colour, 24-bit depth, double buffered: what windows use; offscreen targets add their own FBO. */
    public static GLCapabilities capabilities() {
        GLCapabilities caps = new GLCapabilities(coreProfile());
        caps.setRedBits(8);
        caps.setGreenBits(8);
        caps.setBlueBits(8);
        caps.setAlphaBits(8);
        caps.setDepthBits(24);
        return caps;
    }
}
