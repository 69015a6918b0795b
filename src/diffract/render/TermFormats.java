package diffract.render;

import diffract.jrtr.textures.FloatTextureArray;
import diffract.optics.settings.TermFormat;

/** The engine's texture precision of each {@link TermFormat}. */
public final class TermFormats {
    private TermFormats() {
    }

    /** RG32F: float32; RG16F: half precision; RG8: unsigned normalised bytes. */
    public static FloatTextureArray.Precision precision(TermFormat format) {
        switch (format) {
            case RG16F:
                return FloatTextureArray.Precision.FLOAT16;
            case RG8:
                return FloatTextureArray.Precision.UNORM8;
            default:
                return FloatTextureArray.Precision.FLOAT32;
        }
    }
}
