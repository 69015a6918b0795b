package diffract.jrtr.textures;

import com.jogamp.common.nio.Buffers;
import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL3;

import java.awt.image.BufferedImage;
import java.nio.ByteBuffer;

/**
 * An RGBA8 texture from an image, bytes copied as they are (no sRGB conversion). Rows are uploaded bottom-up
 * so texcoord (0,0) is the image's bottom-left corner, as OpenGL expects. Linear filtering with mipmaps,
 * repeating.
 */
public final class Texture2D extends Texture {
    private final BufferedImage image;

    public Texture2D(BufferedImage image) {
        this.image = image;
    }

    public int width() {
        return image.getWidth();
    }

    public int height() {
        return image.getHeight();
    }

    @Override
    public int glTarget() {
        return GL.GL_TEXTURE_2D;
    }

    @Override
    protected void fill(GL3 gl) {
        int width = image.getWidth();
        int height = image.getHeight();
        int[] argb = image.getRGB(0, 0, width, height, null, 0, width);
        ByteBuffer rgba = Buffers.newDirectByteBuffer(width * height * 4);
        for (int y = height - 1; y >= 0; y--) {
            for (int x = 0; x < width; x++) {
                int p = argb[y * width + x];
                rgba.put((byte) (p >>> 16)).put((byte) (p >>> 8)).put((byte) p).put((byte) (p >>> 24));
            }
        }
        rgba.flip();
        gl.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA8, width, height, 0, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, rgba);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_LINEAR_MIPMAP_LINEAR);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_LINEAR);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_S, GL.GL_REPEAT);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_T, GL.GL_REPEAT);
        gl.glGenerateMipmap(GL.GL_TEXTURE_2D);
    }

    @Override
    public String toString() {
        return "Texture2D[" + image.getWidth() + "x" + image.getHeight() + "]";
    }
}
