package diffract.optics.io;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/**
 * Writes .gwy bytes from the published layout (Gwyddion user guide, "Format of Gwyddion Files"), so that tests
 * build the files they read, damaged ones included: the magic GWYP and one object; an object is its NUL-terminated
 * type name, a uint32 byte count and its components; a component is its NUL-terminated name, a type character and
 * its data, all little-endian.
 */
public final class GwyTestWriter {
    private GwyTestWriter() {
    }

    /** A file: GWYP and the serialised top-level object. */
    public static byte[] file(byte[] object) {
        return concat("GWYP".getBytes(StandardCharsets.US_ASCII), object);
    }

    /** An object of {@code type} holding the components (each from {@link #component}). */
    public static byte[] object(String type, byte[]... components) {
        byte[] body = concat(components);
        return concat(cString(type), le(4).putInt(body.length).array(), body);
    }

    public static byte[] component(String name, char type, byte[] data) {
        return concat(cString(name), new byte[] {(byte) type}, data);
    }

    public static byte[] int32(String name, int value) {
        return component(name, 'i', le(4).putInt(value).array());
    }

    public static byte[] float64(String name, double value) {
        return component(name, 'd', le(8).putDouble(value).array());
    }

    public static byte[] string(String name, String value) {
        return component(name, 's', cString(value));
    }

    public static byte[] objectComponent(String name, byte[] object) {
        return component(name, 'o', object);
    }

    public static byte[] doubles(String name, double[] values) {
        ByteBuffer b = le(4 + 8 * values.length).putInt(values.length);
        for (double v : values) {
            b.putDouble(v);
        }
        return component(name, 'D', b.array());
    }

    /** A GwySIUnit object with its "unitstr". */
    public static byte[] unit(String unit) {
        return object("GwySIUnit", string("unitstr", unit));
    }

    /**
     * A GwyDataField as Gwyddion writes one: xres, yres, xreal, yreal, the units (omitted when null) and data,
     * row by row from the top.
     */
    public static byte[] dataField(int xres, int yres, double xreal, double yreal, String xyUnit, String zUnit,
                                   double[] data) {
        return object("GwyDataField", int32("xres", xres), int32("yres", yres), float64("xreal", xreal),
                float64("yreal", yreal), float64("xoff", 0), float64("yoff", 0),
                xyUnit == null ? new byte[0] : objectComponent("si_unit_xy", unit(xyUnit)),
                zUnit == null ? new byte[0] : objectComponent("si_unit_z", unit(zUnit)),
                doubles("data", data));
    }

    /** Channel N of a container: the data field at "/N/data" and its title at "/N/data/title". */
    public static byte[] channel(int index, String title, byte[] dataField) {
        return concat(objectComponent("/" + index + "/data", dataField), string("/" + index + "/data/title", title));
    }

    /** A whole file of a GwyContainer holding the components (channels, masks, anything else). */
    public static byte[] container(byte[]... components) {
        return file(object("GwyContainer", components));
    }

    /** A one-channel file of heights in metres on square pixels of {@code pixelM} metres. */
    public static byte[] heightsInMetres(int xres, int yres, double pixelM, double[] metres) {
        return container(channel(0, "Height", dataField(xres, yres, xres * pixelM, yres * pixelM, "m", "m", metres)));
    }

    private static byte[] cString(String s) {
        return concat(s.getBytes(StandardCharsets.UTF_8), new byte[1]);
    }

    private static ByteBuffer le(int bytes) {
        return ByteBuffer.allocate(bytes).order(ByteOrder.LITTLE_ENDIAN);
    }

    static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] part : parts) {
            out.writeBytes(part);
        }
        return out.toByteArray();
    }
}
