package diffract.app;

import com.code_intelligence.jazzer.junit.FuzzTest;
import diffract.app.jobs.PieceFolder;
import diffract.geometry.ObjReader;
import diffract.geometry.TangentSource;
import diffract.optics.io.HeightFieldReader;
import diffract.precompute.TermFolders;
import diffract.scene.SceneFile;
import diffract.util.DiskCache;
import diffract.util.Reporter;
import diffract.util.UserInputException;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Comparator;
import java.util.stream.Stream;

/**
 * Every parser of outside input, fed whatever bytes a fuzzer makes: each input must end read or refused in one line
 * (a {@link UserInputException} whose message is a single line); any other exception, an error (a stack overflow,
 * an exhausted heap) or a multi-line message is a failure. Jazzer's JUnit integration replays the committed corpus,
 * {@code tests/fuzz/diffract/app/ParsersFuzzTestInputs/METHOD/}, under the README's test command (regression mode);
 * {@code JAZZER_FUZZ=1} fuzzes (docs/measurements/fuzzing.md has the long run's command and what it found).
 *
 * <p>Targets: every height-field reader (the last byte of an input picks the file's extension, so that both
 * recognition by content and the extension's fallback are fuzzed), scene files, OBJ meshes, folders of Taylor terms
 * (both formats), disk-cache entries and piece manifests.
 */
class ParsersFuzzTest {
    /** Extensions the height-field target names its input by: known, instrument, misleading and none. */
    static final String[] EXTENSIONS = {"gsf", "gwy", "ibw", "spm", "001", "jpk", "tiff", "mdt", "nid", "png", "bmp",
        "txt", "csv", "bin", ""};

    @FuzzTest(maxDuration = "60m", maxExecutions = 500_000)
    void heightFields(byte[] input) {
        if (input.length == 0) {
            return;
        }
        String ext = EXTENSIONS[(input[input.length - 1] & 0xFF) % EXTENSIONS.length];
        byte[] content = Arrays.copyOf(input, input.length - 1);
        Path name = Path.of(ext.isEmpty() ? "fuzz" : "fuzz." + ext);
        oneLineOrRead(() -> HeightFieldReader.read(name, content, null, null, null, null, Reporter.SILENT));
        oneLineOrRead(() -> HeightFieldReader.read(name, content, 0.5, 0.1, null, null, Reporter.SILENT));
    }

    @FuzzTest(maxDuration = "20m", maxExecutions = 100_000)
    void sceneFiles(byte[] input) {
        String text = new String(input, StandardCharsets.UTF_8);
        oneLineOrRead(() -> SceneFile.parse(text, "fuzz.json", Path.of("."), null));
    }

    @FuzzTest(maxDuration = "20m", maxExecutions = 100_000)
    void objMeshes(byte[] input) {
        String text = new String(input, StandardCharsets.UTF_8);
        oneLineOrRead(() -> ObjReader.parse(text, "fuzz.obj", TangentSource.fromUvs()));
    }

    /** The input split at its first NUL: the sidecar (or extrema.txt) and the data (or AmpReIm0.txt). */
    @FuzzTest(maxDuration = "20m", maxExecutions = 100_000)
    void termFolders(byte[] input) throws IOException {
        int split = indexOf(input, (byte) 0);
        byte[] first = split < 0 ? input : Arrays.copyOf(input, split);
        byte[] second = split < 0 ? new byte[0] : Arrays.copyOfRange(input, split + 1, input.length);
        boolean thesis = input.length > 0 && (input[input.length - 1] & 1) == 1;
        Path dir = Files.createTempDirectory("fuzz-terms");
        try {
            Files.write(dir.resolve(thesis ? "extrema.txt" : "terms.json"), first);
            Files.write(dir.resolve(thesis ? "AmpReIm0.txt" : "terms.f32"), second);
            oneLineOrRead(() -> TermFolders.read(dir, Reporter.SILENT));
        } finally {
            delete(dir);
        }
    }

    /** A cache entry is never an error: a damaged one is a warning and is made again. */
    @FuzzTest(maxDuration = "20m", maxExecutions = 100_000)
    void cacheEntries(byte[] input) throws IOException {
        Path dir = Files.createTempDirectory("fuzz-cache");
        try {
            DiskCache cache = DiskCache.at(dir);
            DiskCache.Key key = new DiskCache.Key("terms", "fuzz entry");
            Files.createDirectories(cache.file(key).getParent());
            Files.write(cache.file(key), input);
            oneLineOrRead(() -> cache.load(key, in -> {
                float[] floats = new float[Math.max(0, Math.min(in.readInt(), 1 << 16))];
                DiskCache.readFloats(in, floats);
                return floats;
            }, Reporter.SILENT, "computing it again"));
        } finally {
            delete(dir);
        }
    }

    @FuzzTest(maxDuration = "20m", maxExecutions = 100_000)
    void pieceManifests(byte[] input) throws IOException {
        Path dir = Files.createTempDirectory("fuzz-pieces");
        try {
            Files.write(dir.resolve("piece-1-of-1.json"), input);
            oneLineOrRead(() -> {
                try {
                    return PieceFolder.read(dir);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
        } finally {
            delete(dir);
        }
    }

    /** Runs a parser: a result or a one-line refusal pass; anything else is thrown to the fuzzer. */
    static void oneLineOrRead(java.util.function.Supplier<?> parser) {
        try {
            parser.get();
        } catch (UserInputException e) {
            String m = e.getMessage();
            if (m == null || m.isBlank() || m.contains("\n") || m.contains("\r")) {
                throw new AssertionError("a refusal that is not one line: " + m, e);
            }
        }
    }

    private static int indexOf(byte[] b, byte value) {
        for (int i = 0; i < b.length; i++) {
            if (b[i] == value) {
                return i;
            }
        }
        return -1;
    }

    private static void delete(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
    }
}
