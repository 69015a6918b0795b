package diffract.util;

import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;
import java.awt.image.BufferedImage;
import java.awt.image.IndexColorModel;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Animated GIFs with javax.imageio's GIF writer: every frame shares one 256-colour palette chosen by median cut over
 * the colours of all frames (P. Heckbert, "Color Image Quantization for Frame Buffer Display", SIGGRAPH 1982: split
 * the box of colours with the most pixels along its longest axis at the median, until 256 boxes; each box's mean is
 * a palette entry), pixels mapped to the nearest entry; the NETSCAPE2.0 application extension makes it loop forever.
 */
public final class AnimatedGif {
    private AnimatedGif() {
    }

    /** Writes display-sRGB frames (RGB floats in [0, 1], rows top-down) as a looping GIF, {@code delayMs} per frame. */
    public static void write(Path file, List<float[]> frames, int width, int height, int delayMs) throws IOException {
        if (frames.isEmpty()) {
            throw new IllegalArgumentException("no frames");
        }
        List<int[]> rgbFrames = new ArrayList<>();
        for (float[] frame : frames) {
            int[] rgb = new int[width * height];
            for (int p = 0; p < rgb.length; p++) {
                rgb[p] = byteOf(frame[3 * p]) << 16 | byteOf(frame[3 * p + 1]) << 8 | byteOf(frame[3 * p + 2]);
            }
            rgbFrames.add(rgb);
        }
        int[] palette = palette(rgbFrames, 256);
        byte[] r = new byte[palette.length];
        byte[] g = new byte[palette.length];
        byte[] b = new byte[palette.length];
        for (int i = 0; i < palette.length; i++) {
            r[i] = (byte) (palette[i] >> 16);
            g[i] = (byte) (palette[i] >> 8);
            b[i] = (byte) palette[i];
        }
        IndexColorModel model = new IndexColorModel(8, palette.length, r, g, b);
        // through a temporary file and a rename, as every picture: a special file at the name is left alone
        ImageFiles.writeAtomically(file, stream -> {
            ImageWriter writer = ImageIO.getImageWritersByFormatName("gif").next();
            try (ImageOutputStream out = ImageIO.createImageOutputStream(stream)) {
                writer.setOutput(out);
                writer.prepareWriteSequence(null);
                java.util.Map<Integer, Integer> nearest = new java.util.HashMap<>();
                for (int f = 0; f < rgbFrames.size(); f++) {
                    BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_BYTE_INDEXED, model);
                    int[] rgb = rgbFrames.get(f);
                    byte[] indices = new byte[rgb.length];
                    for (int p = 0; p < rgb.length; p++) {
                        indices[p] = (byte) (int) nearest.computeIfAbsent(rgb[p], c -> nearestIndex(palette, c));
                    }
                    image.getRaster().setDataElements(0, 0, width, height, indices);
                    ImageWriteParam param = writer.getDefaultWriteParam();
                    IIOMetadata metadata = writer.getDefaultImageMetadata(
                            ImageTypeSpecifier.createFromRenderedImage(image), param);
                    configure(metadata, delayMs, f == 0, palette);
                    writer.writeToSequence(new IIOImage(image, null, metadata), param);
                }
                writer.endWriteSequence();
            } finally {
                writer.dispose();
            }
        });
    }

    private static int byteOf(float v) {
        return Math.max(0, Math.min(255, Math.round(v * 255)));
    }

    private static void configure(IIOMetadata metadata, int delayMs, boolean first, int[] palette) throws IOException {
        String format = metadata.getNativeMetadataFormatName();
        IIOMetadataNode root = (IIOMetadataNode) metadata.getAsTree(format);
        // the palette as each frame's local colour table: without one the writer maps indices through its default
        IIOMetadataNode table = child(root, "LocalColorTable");
        while (table.getLength() > 0) {
            table.removeChild(table.getFirstChild());
        }
        table.setAttribute("sizeOfLocalColorTable", "256");
        table.setAttribute("sortFlag", "FALSE");
        for (int i = 0; i < 256; i++) {
            int c = i < palette.length ? palette[i] : 0;
            IIOMetadataNode entry = new IIOMetadataNode("ColorTableEntry");
            entry.setAttribute("index", Integer.toString(i));
            entry.setAttribute("red", Integer.toString((c >> 16) & 0xFF));
            entry.setAttribute("green", Integer.toString((c >> 8) & 0xFF));
            entry.setAttribute("blue", Integer.toString(c & 0xFF));
            table.appendChild(entry);
        }
        IIOMetadataNode control = child(root, "GraphicControlExtension");
        control.setAttribute("disposalMethod", "none");
        control.setAttribute("userInputFlag", "FALSE");
        control.setAttribute("transparentColorFlag", "FALSE");
        control.setAttribute("delayTime", Integer.toString(Math.max(1, delayMs / 10)));
        control.setAttribute("transparentColorIndex", "0");
        if (first) {
            IIOMetadataNode applications = child(root, "ApplicationExtensions");
            IIOMetadataNode loop = new IIOMetadataNode("ApplicationExtension");
            loop.setAttribute("applicationID", "NETSCAPE");
            loop.setAttribute("authenticationCode", "2.0");
            loop.setUserObject(new byte[] {1, 0, 0}); // sub-block 1: loop count 0 = forever
            applications.appendChild(loop);
        }
        metadata.setFromTree(format, root);
    }

    private static IIOMetadataNode child(IIOMetadataNode root, String name) {
        for (int i = 0; i < root.getLength(); i++) {
            if (root.item(i).getNodeName().equalsIgnoreCase(name)) {
                return (IIOMetadataNode) root.item(i);
            }
        }
        IIOMetadataNode node = new IIOMetadataNode(name);
        root.appendChild(node);
        return node;
    }

    /** Median-cut palette of at most {@code size} colours over all pixels of all frames. */
    static int[] palette(List<int[]> frames, int size) {
        int total = 0;
        for (int[] f : frames) {
            total += f.length;
        }
        // a sample of at most 2^20 pixels keeps the cut fast; it sees every frame
        int step = Math.max(1, total / (1 << 20));
        List<Integer> sample = new ArrayList<>();
        int k = 0;
        for (int[] f : frames) {
            for (int c : f) {
                if (k++ % step == 0) {
                    sample.add(c);
                }
            }
        }
        List<List<Integer>> boxes = new ArrayList<>();
        boxes.add(sample);
        while (boxes.size() < size) {
            int largest = -1;
            for (int i = 0; i < boxes.size(); i++) {
                if (boxes.get(i).size() > 1 && spread(boxes.get(i))[0] > 0
                        && (largest < 0 || boxes.get(i).size() > boxes.get(largest).size())) {
                    largest = i;
                }
            }
            if (largest < 0) {
                break;
            }
            List<Integer> box = boxes.remove(largest);
            int shift = spread(box)[1];
            box.sort((a, c) -> Integer.compare((a >> shift) & 0xFF, (c >> shift) & 0xFF));
            int half = box.size() / 2;
            boxes.add(new ArrayList<>(box.subList(0, half)));
            boxes.add(new ArrayList<>(box.subList(half, box.size())));
        }
        int[] palette = new int[boxes.size()];
        for (int i = 0; i < boxes.size(); i++) {
            long[] sum = new long[3];
            for (int c : boxes.get(i)) {
                sum[0] += (c >> 16) & 0xFF;
                sum[1] += (c >> 8) & 0xFF;
                sum[2] += c & 0xFF;
            }
            int n = Math.max(1, boxes.get(i).size());
            palette[i] = (int) (sum[0] / n) << 16 | (int) (sum[1] / n) << 8 | (int) (sum[2] / n);
        }
        return palette;
    }

    /** {range, shift} of the channel with the widest range in a box of colours. */
    private static int[] spread(List<Integer> box) {
        int best = -1;
        int bestShift = 16;
        for (int shift = 16; shift >= 0; shift -= 8) {
            int min = 255;
            int max = 0;
            for (int c : box) {
                int v = (c >> shift) & 0xFF;
                min = Math.min(min, v);
                max = Math.max(max, v);
            }
            if (max - min > best) {
                best = max - min;
                bestShift = shift;
            }
        }
        return new int[] {best, bestShift};
    }

    private static int nearestIndex(int[] palette, int c) {
        int best = 0;
        long bestDistance = Long.MAX_VALUE;
        for (int i = 0; i < palette.length; i++) {
            long dr = ((c >> 16) & 0xFF) - ((palette[i] >> 16) & 0xFF);
            long dg = ((c >> 8) & 0xFF) - ((palette[i] >> 8) & 0xFF);
            long db = (c & 0xFF) - (palette[i] & 0xFF);
            long d = 3 * dr * dr + 4 * dg * dg + 2 * db * db;
            if (d < bestDistance) {
                bestDistance = d;
                best = i;
            }
        }
        return best;
    }
}
