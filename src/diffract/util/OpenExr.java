package diffract.util;

import org.lwjgl.PointerBuffer;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;
import org.lwjgl.util.tinyexr.EXRAttribute;
import org.lwjgl.util.tinyexr.EXRChannelInfo;
import org.lwjgl.util.tinyexr.EXRHeader;
import org.lwjgl.util.tinyexr.EXRImage;
import org.lwjgl.util.tinyexr.EXRVersion;
import org.lwjgl.util.tinyexr.TinyEXR;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * OpenEXR files through tinyexr (LWJGL's binding): one scan-line part of linear floats, 32-bit or half, ZIP
 * compressed (lossless). Pixels are row-major from the top-left, {@code channels} (1 or 3) interleaved floats per
 * pixel, as {@link ImageFiles} takes them. Colour is written as R, G and B of linear sRGB, and the header says so in
 * the standard {@code chromaticities} attribute (Rec. 709 primaries, D65 white): a reader needs no convention to know
 * what the numbers mean. One channel is written as Y, without chromaticities (it is no colour). The file is made in
 * memory and written through {@link ImageFiles#writeAtomically}.
 */
public final class OpenExr {
    /** How each value is stored. */
    public enum Precision {
        /** 32-bit IEEE float: the values exactly. */
        FLOAT,
        /** 16-bit half float: 11 significant bits, largest finite value 65504 (larger ones become infinity). */
        HALF
    }

    /** CIE xy of the Rec. 709 (sRGB) red, green and blue primaries and of the D65 white point (IEC 61966-2-1). */
    public static final float[] REC709_D65_CHROMATICITIES = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f,
            0.3290f};

    /** What {@link #read} found: the size, the channels by name and, where present, the chromaticities. */
    public record Image(int width, int height, List<String> channelNames, List<float[]> channelPlanes,
                        float[] chromaticities) {
        /** The plane (top-down rows) of a channel, or null. */
        public float[] channel(String name) {
            int i = channelNames.indexOf(name);
            return i < 0 ? null : channelPlanes.get(i);
        }
    }

    private OpenExr() {
    }

    /**
     * Writes linear values: three channels as linear sRGB (R, G, B, with the chromaticities), one as Y.
     *
     * @param comment free text for the standard {@code comments} attribute (what the values are), or null
     */
    public static void write(Path file, float[] pixels, int width, int height, int channels, Precision precision,
                             String comment) throws IOException {
        if (channels != 1 && channels != 3) {
            throw new IllegalArgumentException("channels must be 1 or 3, got " + channels);
        }
        if (pixels.length != (long) width * height * channels) {
            throw new IllegalArgumentException("expected " + (long) width * height * channels + " values, got "
                    + pixels.length);
        }
        byte[] bytes = encode(pixels, width, height, channels, precision, comment);
        ImageFiles.writeAtomically(file, out -> out.write(bytes));
    }

    /** The channels as written: alphabetical, as the format lays them out and readers expect them (B, G, R). */
    private static String[] names(int channels) {
        return channels == 1 ? new String[] {"Y"} : new String[] {"B", "G", "R"};
    }

    /** The index within an interleaved pixel of each written channel. */
    private static int[] sources(int channels) {
        return channels == 1 ? new int[] {0} : new int[] {2, 1, 0};
    }

    private static byte[] encode(float[] pixels, int width, int height, int channels, Precision precision,
                                 String comment) throws IOException {
        String[] names = names(channels);
        int[] sources = sources(channels);
        int n = width * height;
        List<FloatBuffer> planes = new ArrayList<>();
        try (MemoryStack stack = MemoryStack.stackPush()) {
            PointerBuffer images = stack.mallocPointer(channels);
            for (int c = 0; c < channels; c++) {
                FloatBuffer plane = MemoryUtil.memAllocFloat(n);
                planes.add(plane);
                for (int p = 0; p < n; p++) {
                    plane.put(p, pixels[p * channels + sources[c]]);
                }
                images.put(c, plane);
            }
            EXRHeader header = EXRHeader.calloc(stack);
            TinyEXR.InitEXRHeader(header);
            EXRChannelInfo.Buffer infos = EXRChannelInfo.calloc(channels, stack);
            IntBuffer given = stack.mallocInt(channels);
            IntBuffer stored = stack.mallocInt(channels);
            for (int c = 0; c < channels; c++) {
                infos.get(c).name(stack.ASCII(names[c]));
                given.put(c, TinyEXR.TINYEXR_PIXELTYPE_FLOAT);
                stored.put(c, precision == Precision.HALF ? TinyEXR.TINYEXR_PIXELTYPE_HALF
                        : TinyEXR.TINYEXR_PIXELTYPE_FLOAT);
            }
            header.num_channels(channels).channels(infos).pixel_types(given).requested_pixel_types(stored)
                    .compression_type(TinyEXR.TINYEXR_COMPRESSIONTYPE_ZIP);
            List<String[]> textAttributes = new ArrayList<>();
            if (comment != null) {
                textAttributes.add(new String[] {"comments", comment});
            }
            EXRAttribute.Buffer attributes = EXRAttribute.calloc((channels == 3 ? 1 : 0) + textAttributes.size(),
                    stack);
            int a = 0;
            if (channels == 3) {
                ByteBuffer xy = stack.malloc(4 * REC709_D65_CHROMATICITIES.length).order(ByteOrder.LITTLE_ENDIAN);
                for (float v : REC709_D65_CHROMATICITIES) {
                    xy.putFloat(v);
                }
                xy.flip();
                attributes.get(a++).name(stack.ASCII("chromaticities")).type(stack.ASCII("chromaticities")).value(xy);
            }
            for (String[] text : textAttributes) {
                // an OpenEXR string attribute is its bytes without a terminating NUL
                attributes.get(a++).name(stack.ASCII(text[0])).type(stack.ASCII("string"))
                        .value(stack.bytes(text[1].getBytes(StandardCharsets.UTF_8)));
            }
            header.custom_attributes(attributes).num_custom_attributes(attributes.capacity());

            EXRImage image = EXRImage.calloc(stack);
            TinyEXR.InitEXRImage(image);
            image.num_channels(channels).width(width).height(height).images(images);

            PointerBuffer memory = stack.callocPointer(1);
            PointerBuffer error = stack.callocPointer(1);
            long size = TinyEXR.SaveEXRImageToMemory(image, header, memory, error);
            if (size == 0) {
                throw new IOException("cannot encode the OpenEXR picture: " + message(error, 0));
            }
            try {
                if (size > Integer.MAX_VALUE - 8) {
                    throw new IOException("the OpenEXR picture is larger than 2 GB");
                }
                byte[] bytes = new byte[(int) size];
                MemoryUtil.memByteBuffer(memory.get(0), (int) size).get(bytes);
                return bytes;
            } finally {
                MemoryUtil.nmemFree(memory.get(0));
            }
        } finally {
            planes.forEach(MemoryUtil::memFree);
        }
    }

    /**
     * Reads a scan-line OpenEXR file with tinyexr, every channel as 32-bit floats.
     *
     * @throws IOException naming what is wrong when the file is no OpenEXR picture tinyexr reads
     */
    public static Image read(Path file) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        ByteBuffer memory = MemoryUtil.memAlloc(Math.max(1, bytes.length));
        try (MemoryStack stack = MemoryStack.stackPush()) {
            memory.put(bytes).flip();
            EXRVersion version = EXRVersion.calloc(stack);
            int code = TinyEXR.ParseEXRVersionFromMemory(version, memory);
            if (code != TinyEXR.TINYEXR_SUCCESS) {
                throw new IOException("not an OpenEXR file (tinyexr code " + code + ")");
            }
            if (version.multipart() || version.non_image()) {
                throw new IOException("a multi-part or deep OpenEXR file; one scan-line or tiled part is read");
            }
            EXRHeader header = EXRHeader.calloc(stack);
            TinyEXR.InitEXRHeader(header);
            PointerBuffer error = stack.callocPointer(1);
            code = TinyEXR.ParseEXRHeaderFromMemory(header, version, memory, error);
            if (code != TinyEXR.TINYEXR_SUCCESS) {
                throw new IOException("bad OpenEXR header: " + message(error, code));
            }
            try {
                return readImage(header, memory, stack);
            } finally {
                TinyEXR.FreeEXRHeader(header);
            }
        } finally {
            MemoryUtil.memFree(memory);
        }
    }

    private static Image readImage(EXRHeader header, ByteBuffer memory, MemoryStack stack) throws IOException {
        int channels = header.num_channels();
        IntBuffer requested = header.requested_pixel_types();
        for (int c = 0; c < channels; c++) {
            requested.put(c, TinyEXR.TINYEXR_PIXELTYPE_FLOAT); // halves come back widened
        }
        float[] chromaticities = null;
        EXRAttribute.Buffer attributes = header.custom_attributes();
        for (int a = 0; attributes != null && a < header.num_custom_attributes(); a++) {
            EXRAttribute attribute = attributes.get(a);
            if (attribute.nameString().equals("chromaticities") && attribute.size() == 32) {
                FloatBuffer xy = attribute.value().order(ByteOrder.LITTLE_ENDIAN).asFloatBuffer();
                chromaticities = new float[8];
                xy.get(chromaticities);
            }
        }
        EXRImage image = EXRImage.calloc(stack);
        TinyEXR.InitEXRImage(image);
        PointerBuffer error = stack.callocPointer(1);
        int code = TinyEXR.LoadEXRImageFromMemory(image, header, memory, error);
        if (code != TinyEXR.TINYEXR_SUCCESS) {
            throw new IOException("cannot read the OpenEXR picture: " + message(error, code));
        }
        try {
            if (image.images() == null) {
                throw new IOException("a tiled OpenEXR file; only scan-line files are read");
            }
            int n = image.width() * image.height();
            List<String> names = new ArrayList<>();
            List<float[]> planes = new ArrayList<>();
            for (int c = 0; c < channels; c++) {
                names.add(header.channels().get(c).nameString());
                float[] plane = new float[n];
                MemoryUtil.memFloatBuffer(image.images().get(c), n).get(plane);
                planes.add(plane);
            }
            return new Image(image.width(), image.height(), List.copyOf(names), List.copyOf(planes),
                    chromaticities == null ? null : Arrays.copyOf(chromaticities, 8));
        } finally {
            TinyEXR.FreeEXRImage(image);
        }
    }

    /** tinyexr's error text (freed here), or its code. */
    private static String message(PointerBuffer error, int code) {
        long text = error.get(0);
        if (text == 0) {
            return "tinyexr code " + code;
        }
        String message = MemoryUtil.memUTF8(text);
        TinyEXR.nFreeEXRErrorMessage(text);
        return message;
    }
}
