package diffract.optics.io;

import diffract.util.UserInputException;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * The height-field formats read, each recognised by its content (magic bytes and headers) wherever it can be, so
 * that a file loads whatever its name; the extension decides only for text matrices and for a damaged file whose
 * content is recognised by nothing (its reader then says what is wrong).
 */
public enum ScanFormat {
    GSF("a Gwyddion Simple Field", "Gwyddion Simple Field (.gsf)", false, "gsf"),
    GWY("a Gwyddion file", "Gwyddion (.gwy)", true, "gwy"),
    IBW("an Igor binary wave", "Igor binary wave (.ibw, Asylum Research)", true, "ibw"),
    NANOSCOPE("a Bruker NanoScope file", "Bruker NanoScope (.spm, .di, .000, .001, ...)", true, "spm", "di"),
    JPK("a JPK scan", "JPK (.jpk)", true, "jpk", "jpk-qi-image"),
    PARK("a Park Systems TIFF", "Park Systems (.tiff)", true),
    MDT("an NT-MDT file", "NT-MDT (.mdt)", true, "mdt"),
    NID("a Nanosurf scan", "Nanosurf (.nid)", true, "nid"),
    IMAGE("a grey image", "grey images (.png, .bmp, .tif, .tiff)", false, "png", "bmp", "tif", "tiff"),
    TEXT("a text matrix", "text matrices (.txt, .csv, .asc, .dat)", false, "txt", "csv", "asc", "dat");

    private final String words;
    private final String listed;
    private final boolean channels;
    private final List<String> extensions;

    ScanFormat(String words, String listed, boolean channels, String... extensions) {
        this.words = words;
        this.listed = listed;
        this.channels = channels;
        this.extensions = List.of(extensions);
    }

    /** "a Bruker NanoScope file". */
    public String words() {
        return words;
    }

    /** Whether the format holds several channels to choose from ({@code channels}, {@code --channel}). */
    public boolean hasChannels() {
        return channels;
    }

    /** The instruments' own files, which hold a scan as measured (levelled by default); exports are level. */
    public boolean isInstrumentFile() {
        return channels;
    }

    /** Every format read, for messages: "Gwyddion Simple Field (.gsf), Gwyddion (.gwy), ...". */
    public static String listing() {
        return Arrays.stream(values()).map(f -> f.listed).collect(Collectors.joining(", "));
    }

    /** The format of these bytes by their content, else by the file's extension. */
    static ScanFormat detect(Path file, byte[] bytes) {
        ScanFormat byContent = byContent(bytes);
        if (byContent != null) {
            return byContent;
        }
        String extension = extension(file);
        if (extension.matches("\\d{3}")) {
            return NANOSCOPE; // NanoScope numbers its files .000, .001, ...
        }
        for (ScanFormat f : values()) {
            if (f.extensions.contains(extension)) {
                return f; // the reader explains what the content should have been
            }
        }
        throw new UserInputException(file + ": not a height-field file diffract reads (its content matches none of"
                + " them" + (extension.isEmpty() ? "" : " and '." + extension + "' is not their extension")
                + "); read are: " + listing());
    }

    /** The format found in the content alone, or null. */
    static ScanFormat byContent(byte[] bytes) {
        if (GsfReader.looksLikeGsf(bytes)) {
            return GSF;
        }
        if (GwyReader.looksLikeGwy(bytes)) {
            return GWY;
        }
        if (NanoscopeReader.looksLikeNanoscope(bytes)) {
            return NANOSCOPE;
        }
        if (MdtReader.looksLikeMdt(bytes)) {
            return MDT;
        }
        if (NidReader.looksLikeNid(bytes)) {
            return NID;
        }
        if (TiffDirectories.looksLikeTiff(bytes)) {
            if (ParkReader.looksLikePark(bytes)) {
                return PARK;
            }
            if (JpkReader.looksLikeJpk(bytes)) {
                return JPK;
            }
            return IMAGE;
        }
        if (ImageHeader.looksLikePngOrBmp(bytes)) {
            return IMAGE;
        }
        if (IbwReader.looksLikeIbw(bytes)) {
            return IBW;
        }
        if (TextMatrixReader.looksLikeText(bytes)) {
            return TEXT;
        }
        return null;
    }

    /** Whether a file of this name would be taken for this format by its extension alone. */
    boolean matchesExtension(Path file) {
        String extension = extension(file);
        return extensions.contains(extension) || this == NANOSCOPE && extension.matches("\\d{3}")
                || this == PARK && (extension.equals("tif") || extension.equals("tiff"));
    }

    private static String extension(Path file) {
        String name = file.getFileName() == null ? "" : file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot < 0 ? "" : name.substring(dot + 1).toLowerCase(Locale.ROOT);
    }
}
