package diffract.jrtr;

import com.jogamp.common.util.VersionNumber;
import diffract.jrtr.gl.GLVersionException;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

/** The version rule, without needing an old driver to provoke it. */
class GLVersionCheckTest {
    @Test
    void olderContextsAreRejectedNamingBothVersions() {
        GLVersionException error = assertThrows(GLVersionException.class, () ->
                GLRenderContext.requireVersion(new VersionNumber(2, 1, 0), false, "2.1 Mesa 22.3.6, llvmpipe"));
        assertEquals("OpenGL 3.3 core or newer required, found OpenGL 2.1 without GL3 core functions"
                + " (2.1 Mesa 22.3.6, llvmpipe)", error.getMessage());
        assertThrows(GLVersionException.class, () ->
                GLRenderContext.requireVersion(new VersionNumber(3, 2, 0), true, "3.2"));
    }

    @Test
    void newEnoughContextsPass() {
        assertDoesNotThrow(() -> GLRenderContext.requireVersion(new VersionNumber(3, 3, 0), true, "3.3"));
        assertDoesNotThrow(() -> GLRenderContext.requireVersion(new VersionNumber(4, 5, 0), true, "4.5"));
    }
}
