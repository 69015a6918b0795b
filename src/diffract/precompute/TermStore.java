package diffract.precompute;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.UserInputException;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.DigestInputStream;
import java.security.DigestOutputStream;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;

/**
 * The project's own on-disk format for precomputed Taylor terms: a folder with
 * <ul>
 *   <li>{@code terms.f32}: term 0, term 1, ..., term N; each term rows x cols texels row by row from texel row 0
 *   (most negative y frequency) and, in a row, from the most negative x frequency; each texel two little-endian
 *   IEEE float32, Re then Im. That is exactly the RG32F texture-array layout a shader uploads, and texel (r, c)
 *   holds frequency index (c - floor(cols/2), r - floor(rows/2)) (003 eq. 1.5). Not normalised: the extrema of
 *   eq. 1.1 are stored for information, the values are the raw DFTs.</li>
 *   <li>{@code terms.json}: the {@link TermSidecar} (patch hash, sizes, N, extrema, data checksum).</li>
 * </ul>
 * Writes go to temporary names and are renamed into place: the old sidecar is removed first and the new one
 * renamed last, so a sidecar always describes the data beside it (a writer killed in between leaves a folder
 * without sidecar, which reads as incomplete). Readers verify size and SHA-256 before trusting the data; whatever
 * fails (an unreadable or incomplete sidecar, missing, truncated or modified data) is a {@link Damaged} folder,
 * which {@link Precomputation} recomputes. Writers hold the folder's {@link diffract.util.FolderLock}.
 */
public final class TermStore {
    public static final String DATA_FILE = "terms.f32";
    public static final String SIDECAR_FILE = "terms.json";
    static final String LAYOUT = "term-major, row-major texels from (-cols/2, -rows/2), (Re, Im) float32 pairs";
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private TermStore() {
    }

    /** A folder whose sidecar or data cannot be trusted: recompute it (the message says what is wrong). */
    public static final class Damaged extends UserInputException {
        private static final long serialVersionUID = 1L;

        Damaged(String message) {
            super(message);
        }

        Damaged(String message, Throwable cause) {
            super(message, cause);
        }
    }

    /** Writes terms and sidecar into {@code dir} (created if needed) and returns the sidecar written. */
    public static TermSidecar write(Path dir, TaylorTerms terms, TermSidecar.Patch patch, TermSidecar.Selection selection,
                                    String toolVersion) throws IOException {
        Files.createDirectories(dir);
        Files.deleteIfExists(dir.resolve(SIDECAR_FILE)); // no moment with the old sidecar beside new data
        Path tmpData = tempSibling(dir.resolve(DATA_FILE));
        String sha;
        long bytes = 0;
        try {
            MessageDigest digest = sha256();
            try (OutputStream out = new DigestOutputStream(
                    new java.io.BufferedOutputStream(Files.newOutputStream(tmpData), 1 << 20), digest)) {
                ByteBuffer buffer = ByteBuffer.allocate(1 << 20).order(ByteOrder.LITTLE_ENDIAN);
                for (int n = 0; n < terms.termCount(); n++) {
                    float[] data = terms.termData(n);
                    for (float f : data) {
                        if (buffer.remaining() < 4) {
                            out.write(buffer.array(), 0, buffer.position());
                            buffer.clear();
                        }
                        buffer.putFloat(f);
                    }
                    bytes += 4L * data.length;
                }
                out.write(buffer.array(), 0, buffer.position());
            }
            sha = HexFormat.of().formatHex(digest.digest());
            Files.move(tmpData, dir.resolve(DATA_FILE), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmpData);
        }
        List<TermSidecar.Extrema> extrema = new ArrayList<>();
        for (int n = 0; n < terms.termCount(); n++) {
            TaylorTerms.Extrema e = terms.extrema(n);
            extrema.add(new TermSidecar.Extrema(n, e.reMin(), e.reMax(), e.imMin(), e.imMax()));
        }
        TermSidecar sidecar = new TermSidecar(TermSidecar.FORMAT, TermSidecar.FORMAT_VERSION, toolVersion, patch,
                terms.highestOrder(), terms.termCount(), selection,
                new TermSidecar.Data(DATA_FILE, LAYOUT, "little-endian", bytes, sha), extrema);
        Path tmpSidecar = tempSibling(dir.resolve(SIDECAR_FILE));
        try {
            JSON.writeValue(tmpSidecar.toFile(), sidecar);
            Files.move(tmpSidecar, dir.resolve(SIDECAR_FILE), StandardCopyOption.REPLACE_EXISTING,
                    StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmpSidecar);
        }
        return sidecar;
    }

    /**
     * The sidecar of {@code dir}, or null when there is none.
     *
     * @throws Damaged when it cannot be parsed or lacks what a reader needs
     */
    public static TermSidecar readSidecar(Path dir) {
        Path file = dir.resolve(SIDECAR_FILE);
        if (!Files.isRegularFile(file)) {
            return null;
        }
        TermSidecar sidecar;
        try {
            sidecar = JSON.readValue(file.toFile(), TermSidecar.class);
        } catch (IOException e) {
            throw new Damaged(file + " is not readable JSON (" + firstLine(e.getMessage()) + ")", e);
        }
        if (sidecar == null || !TermSidecar.FORMAT.equals(sidecar.format())) {
            throw new Damaged(file + " is not a diffract term sidecar (format '"
                    + (sidecar == null ? null : sidecar.format()) + "')");
        }
        if (sidecar.formatVersion() > TermSidecar.FORMAT_VERSION) {
            throw new Damaged(file + " has format version " + sidecar.formatVersion() + "; this build reads up to "
                    + TermSidecar.FORMAT_VERSION);
        }
        String missing = missingField(sidecar);
        if (missing != null) {
            throw new Damaged(file + " is incomplete: " + missing);
        }
        return sidecar;
    }

    /** What a reader needs and the sidecar lacks, or null. */
    private static String missingField(TermSidecar s) {
        TermSidecar.Patch patch = s.patch();
        TermSidecar.Data data = s.data();
        if (patch == null) {
            return "no 'patch'";
        }
        if (data == null) {
            return "no 'data'";
        }
        if (patch.rows() < 1 || patch.cols() < 1 || !(patch.pixelSizeXUm() > 0) || !(patch.pixelSizeYUm() > 0)) {
            return "no valid patch size in 'patch'";
        }
        if (s.termCount() < 1 || s.highestOrder() != s.termCount() - 1) {
            return "'termCount' " + s.termCount() + " does not match 'highestOrder' " + s.highestOrder();
        }
        if (!DATA_FILE.equals(data.file())) {
            return "'data.file' must be " + DATA_FILE + ", got " + data.file();
        }
        if (data.sha256() == null || data.sha256().length() != 64) {
            return "no SHA-256 in 'data'";
        }
        return null;
    }

    /**
     * Verifies the data of {@code dir} against its sidecar (size and SHA-256) without keeping them.
     *
     * @throws Damaged when they do not match
     */
    public static void verify(Path dir, TermSidecar sidecar) {
        readData(dir, sidecar, false);
    }

    /**
     * Reads and verifies (size and SHA-256) the terms of {@code dir}.
     *
     * @throws Damaged when the sidecar or the data cannot be trusted
     * @throws UserInputException when the folder has no sidecar
     */
    public static TaylorTerms read(Path dir) {
        TermSidecar sidecar = readSidecar(dir);
        if (sidecar == null) {
            boolean dataOnly = Files.isRegularFile(dir.resolve(DATA_FILE));
            throw new UserInputException("no " + SIDECAR_FILE + " in " + dir + (dataOnly
                    ? " beside its " + DATA_FILE + " (an interrupted precompute?); run the precompute into it again"
                    : ": not a precomputed term folder (make one with ./diffract precompute ... -o " + dir + ")"));
        }
        return read(dir, sidecar);
    }

    /** The terms of {@code dir} as {@code sidecar} (read before) describes them, verified against it. */
    public static TaylorTerms read(Path dir, TermSidecar sidecar) {
        TermSidecar.Patch patch = sidecar.patch();
        return new TaylorTerms(patch.rows(), patch.cols(), patch.pixelSizeXUm(), patch.pixelSizeYUm(),
                patch.maxAbsHeightUm(), readData(dir, sidecar, true));
    }

    /** A line that says how to repair a damaged folder: run the precompute that made it again. */
    public static String repairHint(Path dir, TermSidecar sidecar) {
        String what = sidecar != null && sidecar.patch() != null && sidecar.patch().source() != null
                ? " (patch " + sidecar.patch().source() + ", N = " + sidecar.highestOrder() + ")" : "";
        return "run the precompute that made it again" + what + " with -o " + dir + ": it repairs the folder";
    }

    private static float[][] readData(Path dir, TermSidecar sidecar, boolean keep) {
        TermSidecar.Patch patch = sidecar.patch();
        long texels = (long) patch.rows() * patch.cols();
        long expected = 8L * texels * sidecar.termCount();
        if (sidecar.data().bytes() != expected || 2 * texels > Integer.MAX_VALUE - 8) {
            throw new Damaged(dir.resolve(SIDECAR_FILE) + " is inconsistent: " + sidecar.data().bytes()
                    + " bytes for " + sidecar.termCount() + " terms of " + patch.rows() + "x" + patch.cols()
                    + " (expected " + expected + ")");
        }
        Path dataFile = dir.resolve(DATA_FILE);
        float[][] terms = keep ? new float[sidecar.termCount()][(int) (2 * texels)] : null;
        MessageDigest digest = sha256();
        try (InputStream in = new DigestInputStream(new java.io.BufferedInputStream(Files.newInputStream(dataFile), 1 << 20), digest)) {
            byte[] bytes = new byte[(int) (8 * texels)];
            for (int n = 0; n < sidecar.termCount(); n++) {
                int read = in.readNBytes(bytes, 0, bytes.length);
                if (read != bytes.length) {
                    throw new Damaged(dataFile + " is truncated (" + Files.size(dataFile) + " of " + expected
                            + " bytes)");
                }
                if (keep) {
                    ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).asFloatBuffer().get(terms[n]);
                }
            }
            if (in.read() != -1) {
                throw new Damaged(dataFile + " is longer than its sidecar says");
            }
        } catch (NoSuchFileException e) {
            throw new Damaged("missing " + dataFile + " next to its sidecar", e);
        } catch (IOException e) {
            throw new Damaged("cannot read " + dataFile + ": " + e.getMessage(), e);
        }
        String sha = HexFormat.of().formatHex(digest.digest());
        if (!sha.equals(sidecar.data().sha256())) {
            throw new Damaged(dataFile + " fails its checksum (corrupt or modified)");
        }
        return terms;
    }

    private static String firstLine(String text) {
        return text == null ? "" : text.lines().findFirst().orElse("");
    }

    private static Path tempSibling(Path file) {
        return file.resolveSibling(file.getFileName() + ".tmp-" + ProcessHandle.current().pid() + "-" + System.nanoTime());
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every Java runtime", e);
        }
    }
}
