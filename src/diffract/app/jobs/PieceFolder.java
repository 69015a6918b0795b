package diffract.app.jobs;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import diffract.util.ImageFiles;
import diffract.util.UserInputException;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.stream.Collectors;

/**
 * A folder of pieces of one result (a BRDF map, a turntable's frames, a bench sweep's rows): {@code brdfmap --tile},
 * {@code render --turntable F --tile} and {@code bench --tile} write one each, {@code merge} reads them all back into
 * the whole result's floats (a bench piece has none: its rows are in its manifest), or refuses,
 * in one line, a folder whose pieces are missing, twice there, damaged or of another result. The floats are written
 * before the manifest, each atomically, so a run that dies leaves no manifest that merge would accept.
 */
public final class PieceFolder {
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
    private static final String MANIFEST = ".json";
    private static final String FLOATS = ".f32";

    private PieceFolder() {
    }

    /**
     * The pieces of a result, assembled: the first manifest (all agree), all the result's floats, and every piece's
     * manifest, in order.
     */
    public record Assembled(PieceManifest manifest, float[] floats, List<PieceManifest> pieces) {
    }

    /** Writes a piece's floats, then its manifest (with the floats' name and hash filled in). */
    public static void write(Path dir, PieceManifest manifest, float[] floats) throws IOException {
        if (floats.length != (long) (manifest.to() - manifest.from()) * manifest.floatsPerItem()) {
            throw new IllegalArgumentException("piece " + manifest.label() + " has " + floats.length + " floats, not "
                    + (manifest.to() - manifest.from()) + " x " + manifest.floatsPerItem());
        }
        byte[] bytes = bytes(floats);
        TileOptions.Tile tile = new TileOptions.Tile(manifest.piece(), manifest.pieces());
        String floatsName = tile.fileName(FLOATS);
        PieceManifest complete = manifest.withFloats(floatsName, sha256(bytes));
        byte[] json = (JSON.writeValueAsString(complete) + "\n").getBytes(java.nio.charset.StandardCharsets.UTF_8);
        ImageFiles.writeAtomically(dir.resolve(floatsName), out -> out.write(bytes));
        ImageFiles.writeAtomically(dir.resolve(tile.fileName(MANIFEST)), out -> out.write(json));
    }

    /** Every piece in {@code dir}, checked against each other and their hashes, as one result. */
    public static Assembled read(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            throw refusal("merge: " + dir + " is not a folder of pieces (brdfmap, render or bench "
                    + "--tile I/N --pieces DIR writes one)");
        }
        Map<Path, PieceManifest> manifests = new TreeMap<>();
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, "*" + MANIFEST)) {
            for (Path file : files) {
                manifests.put(file, parse(file));
            }
        }
        if (manifests.isEmpty()) {
            throw refusal("merge: " + dir + " holds no pieces (piece-I-of-N.json, written by brdfmap, "
                    + "render or bench --tile I/N --pieces " + dir + ")");
        }
        PieceManifest first = agreeing(dir, manifests);
        PieceManifest[] byIndex = complete(dir, manifests, first.pieces());
        long total = (long) first.items() * first.floatsPerItem();
        if (total > Integer.MAX_VALUE - 8) {
            throw refusal("merge: " + dir + ": the result has " + total + " floats, more than one "
                    + "array holds");
        }
        float[] all = new float[(int) total];
        for (PieceManifest m : byIndex) {
            float[] floats = verifiedFloats(dir, m);
            System.arraycopy(floats, 0, all, m.from() * m.floatsPerItem(), floats.length);
        }
        return new Assembled(first, all, List.of(byIndex));
    }

    private static PieceManifest parse(Path file) throws IOException {
        try {
            PieceManifest m = JSON.readValue(file.toFile(), PieceManifest.class);
            if (!PieceManifest.FORMAT.equals(m.format())) {
                throw refusal("merge: " + file + " is not a piece manifest (format '" + m.format()
                        + "', expected '" + PieceManifest.FORMAT + "'): remove it or compute that piece again");
            }
            // a manifest cut short or edited by hand: every field the merge compares must be there
            String missing = m.command() == null ? "command" : m.inputSha256() == null ? "inputSha256"
                    : m.settings() == null ? "settings" : m.picture() == null ? "picture"
                    : m.arguments() == null ? "arguments" : m.floatsFile() == null ? "floatsFile"
                    : m.floatsSha256() == null ? "floatsSha256" : null;
            if (missing != null) {
                throw refusal("merge: " + file + " is not a complete piece manifest (no '" + missing
                        + "'): remove it or compute that piece again");
            }
            return m;
        } catch (JsonProcessingException e) {
            throw refusal("merge: " + file + " is not a piece manifest ("
                    + e.getOriginalMessage().replaceAll("\\s+", " ") + "): remove it or compute that piece again");
        } catch (java.io.CharConversionException e) {
            // bytes that Jackson's encoding detection takes for UTF-16 or UTF-32 and cannot decode
            throw refusal("merge: " + file + " is not a piece manifest (not UTF-8 text: "
                    + e.getMessage().replaceAll("\\s+", " ") + "): remove it or compute that piece again");
        }
    }

    /**
     * The manifest most pieces agree with; pieces of another map (other settings, patch, size or split) are refused,
     * named, with what differs.
     */
    private static PieceManifest agreeing(Path dir, Map<Path, PieceManifest> manifests) {
        Map<List<Object>, List<Path>> groups = new LinkedHashMap<>();
        manifests.forEach((file, m) -> groups.computeIfAbsent(m.resultKey(), k -> new ArrayList<>()).add(file));
        if (groups.size() == 1) {
            return manifests.values().iterator().next();
        }
        List<Path> most = groups.values().stream().max(Comparator.comparingInt(List::size)).orElseThrow();
        PieceManifest reference = manifests.get(most.get(0));
        List<Path> others = manifests.keySet().stream().filter(f -> !most.contains(f)).toList();
        PieceManifest other = manifests.get(others.get(0));
        throw refusal("merge: " + dir + ": " + names(others) + " belong to another "
                + what(reference) + " than " + names(most) + " (" + difference(reference, other) + "): compute them "
                + "again with the same options");
    }

    /** What a piece is part of, in words. */
    private static String what(PieceManifest m) {
        return switch (String.valueOf(m.command())) {
            case "render" -> "turntable";
            case "bench" -> "bench sweep";
            default -> "map";
        };
    }

    /** The first thing that differs between two pieces' results, in words. */
    private static String difference(PieceManifest a, PieceManifest b) {
        if (!Objects.equals(a.command(), b.command())) {
            return "computed by " + b.command() + ", not " + a.command();
        }
        if (a.pieces() != b.pieces()) {
            return "split into " + b.pieces() + " pieces, not " + a.pieces();
        }
        if (!Objects.equals(a.inputSha256(), b.inputSha256())) {
            return "another patch: its height field's SHA-256 differs";
        }
        if (a.items() != b.items() || a.floatsPerItem() != b.floatsPerItem()) {
            return b.items() + " " + items(b) + " of " + b.floatsPerItem() + " floats, not " + a.items() + " of "
                    + a.floatsPerItem();
        }
        String settings = firstDifference(a.settings(), b.settings());
        return settings != null ? settings : Objects.requireNonNullElse(firstDifference(a.picture(), b.picture()),
                "other settings");
    }

    /** The first key whose value differs, as "key B, not A"; null if none does. */
    private static String firstDifference(Map<String, String> a, Map<String, String> b) {
        for (String key : union(a, b)) {
            if (!Objects.equals(a.get(key), b.get(key))) {
                return key + " " + b.get(key) + ", not " + a.get(key);
            }
        }
        return null;
    }

    private static List<String> union(Map<String, String> a, Map<String, String> b) {
        List<String> keys = new ArrayList<>(a.keySet());
        b.keySet().stream().filter(k -> !a.containsKey(k)).forEach(keys::add);
        return keys;
    }

    /** The pieces by index, each there exactly once. */
    private static PieceManifest[] complete(Path dir, Map<Path, PieceManifest> manifests, int count) {
        Map<Integer, List<Path>> byIndex = new TreeMap<>();
        manifests.forEach((file, m) -> byIndex.computeIfAbsent(m.piece(), k -> new ArrayList<>()).add(file));
        List<String> twice = byIndex.entrySet().stream().filter(e -> e.getValue().size() > 1)
                .map(e -> e.getKey() + "/" + count + " (" + names(e.getValue()) + ")").toList();
        if (!twice.isEmpty()) {
            throw refusal("merge: " + dir + ": piece" + (twice.size() > 1 ? "s " : " ")
                    + String.join(", ", twice) + (twice.size() > 1 ? " are" : " is") + " there more than once: "
                    + "remove the extra manifests");
        }
        List<String> missing = new ArrayList<>();
        PieceManifest[] pieces = new PieceManifest[count];
        for (int i = 0; i < count; i++) {
            List<Path> files = byIndex.get(i);
            if (files == null) {
                missing.add(i + "/" + count);
            } else {
                pieces[i] = manifests.get(files.get(0));
            }
        }
        if (!missing.isEmpty()) {
            String command = manifests.values().iterator().next().command();
            throw refusal("merge: " + dir + ": piece" + (missing.size() > 1 ? "s " : " ")
                    + String.join(", ", missing) + (missing.size() > 1 ? " are" : " is") + " missing: run " + command
                    + " --tile " + missing.get(0) + " --pieces " + dir + " with the same options");
        }
        for (PieceManifest m : pieces) {
            TileOptions.Tile tile = new TileOptions.Tile(m.piece(), m.pieces());
            var band = diffract.optics.MapBand.of(m.piece(), m.pieces(), m.items());
            if (band.fromRow() != m.from() || band.toRow() != m.to()) {
                throw refusal("merge: " + dir + ": piece " + tile + " covers " + items(m) + " "
                        + m.from() + ".." + (m.to() - 1) + ", not " + band + ": compute it again");
            }
        }
        return pieces;
    }

    /** What a piece's items are, in words. */
    private static String items(PieceManifest m) {
        return switch (String.valueOf(m.command())) {
            case "render" -> "frames";
            case "bench" -> "configurations";
            default -> "rows";
        };
    }

    /** A piece's floats, if their hash is the manifest's. */
    private static float[] verifiedFloats(Path dir, PieceManifest m) throws IOException {
        String name = m.floatsFile();
        // a manifest names a file beside it, never one elsewhere
        boolean beside = name != null && !name.isEmpty() && Path.of(name).getFileName().toString().equals(name);
        Path file = beside ? dir.resolve(name) : dir;
        if (!beside || !Files.isRegularFile(file)) {
            throw refusal("merge: " + dir + ": piece " + m.label() + "'s floats (" + name
                    + ") are missing: compute that piece again");
        }
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw refusal("merge: " + dir + ": piece " + m.label() + "'s floats (" + name
                    + ") are missing: compute that piece again");
        }
        int expected = (m.to() - m.from()) * m.floatsPerItem();
        if (bytes.length != 4L * expected || !sha256(bytes).equals(m.floatsSha256())) {
            throw refusal("merge: " + dir + ": piece " + m.label() + " is damaged: " + name
                    + " does not match its manifest's SHA-256: compute that piece again");
        }
        float[] floats = new float[expected];
        ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).asFloatBuffer().get(floats);
        return floats;
    }

    private static String names(List<Path> files) {
        return files.stream().map(f -> f.getFileName().toString()).collect(Collectors.joining(", "));
    }

    static byte[] bytes(float[] floats) {
        ByteBuffer buffer = ByteBuffer.allocate(4 * floats.length).order(ByteOrder.LITTLE_ENDIAN);
        buffer.asFloatBuffer().put(floats);
        return buffer.array();
    }

    static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every Java runtime", e);
        }
    }

    /**
     * A one-line refusal: manifests are read from disk and may hold anything, so control characters from them (a
     * line break in a format or a file name) become '?'.
     */
    private static UserInputException refusal(String message) {
        return new UserInputException(message.replaceAll("\\p{Cntrl}", "?"));
    }
}
