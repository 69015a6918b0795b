package diffract.optics.io;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * Writes Igor binary waves of version 5 from the published layout (WaveMetrics' Technical Note PTN003, "Igor
 * Binary Format"), so that tests build the files they read: BinHeader5 (64 bytes: version, checksum, wfmSize,
 * formulaSize, noteSize, dataEUnitsSize, dimEUnitsSize[4], dimLabelsSize[4], sIndicesSize, 2 reserved),
 * WaveHeader5 (320 bytes: npnts at 12, type at 16, bname at 28, nDim[4] at 68, sfA[4] at 84, sfB[4] at 116,
 * dataUnits at 148, dimUnits[4][4] at 152), the data (the first dimension fastest), then the note, the extended
 * data units and the labels of dimension 2 (32 bytes each, the first for the dimension itself). The checksum
 * makes the 16-bit sum of the 384 header bytes 0.
 */
public final class IbwTestWriter {
    public static final int FLOAT32 = 2;
    public static final int FLOAT64 = 4;
    public static final int INT16 = 0x10;
    public static final int UINT16 = 0x50;

    private ByteOrder order = ByteOrder.LITTLE_ENDIAN;
    private int version = 5;
    private int type = FLOAT32;
    private String name = "scan";
    private final int[] nDim = new int[4];
    private final double[] sfA = {1, 1, 1, 1};
    private String dataUnits = "";
    private final String[] dimUnits = {"", "", "", ""};
    private String note = "";
    private String extendedDataUnits = "";
    private List<String> layerLabels = List.of();
    private double[] values = new double[0];
    private Integer npntsOverride;

    /**
     * @param cols   nDim[0], Igor's rows: x
     * @param rows   nDim[1], Igor's columns: y
     * @param layers nDim[2], 0 for a 2-D wave
     * @param values cols x rows (x layers) values, x fastest, Igor's first row (the bottom of the picture) first
     */
    public static IbwTestWriter wave(int cols, int rows, int layers, double[] values) {
        IbwTestWriter w = new IbwTestWriter();
        w.nDim[0] = cols;
        w.nDim[1] = rows;
        w.nDim[2] = layers;
        w.values = values;
        return w;
    }

    public IbwTestWriter order(ByteOrder byteOrder) {
        this.order = byteOrder;
        return this;
    }

    public IbwTestWriter version(int v) {
        this.version = v;
        return this;
    }

    public IbwTestWriter type(int code) {
        this.type = code;
        return this;
    }

    public IbwTestWriter name(String waveName) {
        this.name = waveName;
        return this;
    }

    /** The step per point along x and y (sfA[0], sfA[1]) and their unit. */
    public IbwTestWriter step(double x, double y, String unit) {
        sfA[0] = x;
        sfA[1] = y;
        dimUnits[0] = unit;
        dimUnits[1] = unit;
        return this;
    }

    public IbwTestWriter dataUnits(String units) {
        this.dataUnits = units;
        return this;
    }

    public IbwTestWriter extendedDataUnits(String units) {
        this.extendedDataUnits = units;
        return this;
    }

    public IbwTestWriter note(String text) {
        this.note = text;
        return this;
    }

    /** The labels of the layers (dimension 2), written after an empty one for the dimension itself. */
    public IbwTestWriter layers(String... labels) {
        this.layerLabels = List.of(labels);
        return this;
    }

    public IbwTestWriter npnts(int points) {
        this.npntsOverride = points;
        return this;
    }

    public byte[] bytes() {
        int sampleBytes = switch (type) {
            case FLOAT32 -> 4;
            case FLOAT64 -> 8;
            case INT16, UINT16 -> 2;
            default -> 4; // other codes: written as 4 bytes, for the reader to refuse
        };
        byte[] data = data(sampleBytes);
        byte[] noteBytes = note.getBytes(StandardCharsets.ISO_8859_1);
        byte[] unitBytes = extendedDataUnits.getBytes(StandardCharsets.ISO_8859_1);
        byte[] labels = labels();

        ByteBuffer h = ByteBuffer.allocate(384).order(order);
        h.putShort(0, (short) version);
        h.putInt(4, 320 + data.length); // wfmSize
        h.putInt(12, noteBytes.length);
        h.putInt(16, unitBytes.length);
        h.putInt(36 + 4 * 2, labels.length); // dimLabelsSize[2]
        int w = 64;
        int points = nDim[0] * Math.max(1, nDim[1]) * Math.max(1, nDim[2]);
        h.putInt(w + 12, npntsOverride != null ? npntsOverride : points);
        h.putShort(w + 16, (short) type);
        h.putShort(w + 26, (short) 1); // whVersion
        put(h, w + 28, name, 32);
        for (int d = 0; d < 4; d++) {
            h.putInt(w + 68 + 4 * d, nDim[d]);
            h.putDouble(w + 84 + 8 * d, sfA[d]);
            put(h, w + 152 + 4 * d, dimUnits[d], 4);
        }
        put(h, w + 148, dataUnits, 4);
        int sum = 0;
        for (int i = 0; i < 384; i += 2) {
            sum += h.getShort(i) & 0xFFFF;
        }
        h.putShort(2, (short) (-sum & 0xFFFF)); // the checksum: the sum of all words becomes 0

        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(h.array());
        out.writeBytes(data);
        out.writeBytes(noteBytes);
        out.writeBytes(unitBytes);
        out.writeBytes(labels);
        return out.toByteArray();
    }

    private byte[] data(int sampleBytes) {
        ByteBuffer b = ByteBuffer.allocate(values.length * sampleBytes).order(order);
        for (double v : values) {
            switch (type) {
                case FLOAT64 -> b.putDouble(v);
                case INT16, UINT16 -> b.putShort((short) v);
                default -> b.putFloat((float) v);
            }
        }
        return b.array();
    }

    private byte[] labels() {
        if (layerLabels.isEmpty()) {
            return new byte[0];
        }
        ByteBuffer b = ByteBuffer.allocate(32 * (layerLabels.size() + 1));
        for (int i = 0; i < layerLabels.size(); i++) {
            put(b, 32 * (i + 1), layerLabels.get(i), 32);
        }
        return b.array();
    }

    private static void put(ByteBuffer b, int at, String text, int field) {
        byte[] bytes = text.getBytes(StandardCharsets.ISO_8859_1);
        for (int i = 0; i < Math.min(bytes.length, field - 1); i++) {
            b.put(at + i, bytes[i]);
        }
    }
}
