package diffract.precompute;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import diffract.optics.TaylorTerms;
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
 * Writes go to temporary names and are renamed into place, data first and sidecar last, so a folder with a
 * sidecar always has complete data; readers verify size and SHA-256 before trusting it.
 */
public final class TermStore {
    public static final String DATA_FILE = "terms.f32";
    public static final String SIDECAR_FILE = "terms.json";
    static final String LAYOUT = "term-major, row-major texels from (-cols/2, -rows/2), (Re, Im) float32 pairs";
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private TermStore() {
    }

    /** Writes terms and sidecar into {@code dir} (created if needed) and returns the sidecar written. */
    public static TermSidecar write(Path dir, TaylorTerms terms, TermSidecar.Patch patch, TermSidecar.Selection selection,
                                    String toolVersion) throws IOException {
        Files.createDirectories(dir);
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

    /** The sidecar of {@code dir}, or null when there is none; a sidecar we cannot parse is an error. */
    public static TermSidecar readSidecar(Path dir) {
        Path file = dir.resolve(SIDECAR_FILE);
        if (!Files.isRegularFile(file)) {
            return null;
        }
        try {
            TermSidecar sidecar = JSON.readValue(file.toFile(), TermSidecar.class);
            if (!TermSidecar.FORMAT.equals(sidecar.format())) {
                throw new UserInputException(file + " is not a diffract term sidecar (format '" + sidecar.format() + "')");
            }
            if (sidecar.formatVersion() > TermSidecar.FORMAT_VERSION) {
                throw new UserInputException(file + " has format version " + sidecar.formatVersion()
                        + "; this build reads up to " + TermSidecar.FORMAT_VERSION + ": update diffract or precompute again");
            }
            return sidecar;
        } catch (IOException e) {
            throw new UserInputException("cannot read " + file + " (" + e.getMessage().lines().findFirst().orElse("")
                    + "); delete the folder and precompute again", e);
        }
    }

    /** True when the data file exists with the size the sidecar promises (a cheap check, no hashing). */
    public static boolean dataLooksComplete(Path dir, TermSidecar sidecar) {
        try {
            return Files.size(dir.resolve(sidecar.data().file())) == sidecar.data().bytes();
        } catch (IOException e) {
            return false;
        }
    }

    /** Reads and verifies (size and SHA-256) the terms of {@code dir}. */
    public static TaylorTerms read(Path dir) {
        TermSidecar sidecar = readSidecar(dir);
        if (sidecar == null) {
            throw new UserInputException("no " + SIDECAR_FILE + " in " + dir + ": not a precomputed term folder "
                    + "(make one with ./diffract precompute ... -o " + dir + ")");
        }
        TermSidecar.Patch patch = sidecar.patch();
        int texels = patch.rows() * patch.cols();
        long expected = 8L * texels * sidecar.termCount();
        if (sidecar.data().bytes() != expected) {
            throw new UserInputException(dir.resolve(SIDECAR_FILE) + " is inconsistent: " + sidecar.data().bytes()
                    + " bytes for " + sidecar.termCount() + " terms of " + patch.rows() + "x" + patch.cols()
                    + " (expected " + expected + "); precompute again");
        }
        Path dataFile = dir.resolve(sidecar.data().file());
        float[][] terms = new float[sidecar.termCount()][2 * texels];
        MessageDigest digest = sha256();
        try (InputStream in = new DigestInputStream(new java.io.BufferedInputStream(Files.newInputStream(dataFile), 1 << 20), digest)) {
            byte[] bytes = new byte[8 * texels];
            for (float[] term : terms) {
                int read = in.readNBytes(bytes, 0, bytes.length);
                if (read != bytes.length) {
                    throw new UserInputException(dataFile + " is truncated (" + Files.size(dataFile) + " of "
                            + expected + " bytes); precompute again");
                }
                ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).asFloatBuffer().get(term);
            }
            if (in.read() != -1) {
                throw new UserInputException(dataFile + " is longer than its sidecar says; precompute again");
            }
        } catch (NoSuchFileException e) {
            throw new UserInputException("missing " + dataFile + " next to its sidecar; precompute again", e);
        } catch (IOException e) {
            throw new UserInputException("cannot read " + dataFile + ": " + e.getMessage(), e);
        }
        String sha = HexFormat.of().formatHex(digest.digest());
        if (!sha.equals(sidecar.data().sha256())) {
            throw new UserInputException(dataFile + " fails its checksum (corrupt or modified); delete "
                    + dir + " and precompute again");
        }
        return new TaylorTerms(patch.rows(), patch.cols(), patch.pixelSizeXUm(), patch.pixelSizeYUm(),
                patch.maxAbsHeightUm(), terms);
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
