package diffract.util;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.FileTime;
import java.security.DigestOutputStream;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Clock;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * The user's disk cache of work that is expensive to redo (Taylor terms, baked tables, calibrations of the
 * {@code auto} variant, reference maps), shared by every run and every command. Its folder is the system property
 * {@value #ROOT_PROPERTY}, else {@code $DIFFRACT_CACHE}, else {@code $XDG_CACHE_HOME/diffract}, else
 * {@code ~/.cache/diffract}; one sub-folder per kind of entry ({@link #KINDS}).
 *
 * <p>An entry is named by a digest of its {@link Key}: the content it was made from (a hash of the patch or of the
 * terms) and every setting that changes it, so a changed input finds no entry rather than a stale one. An entry file
 * holds a text header (format, kind, the key in words), the payload, and a trailer with the payload's length and
 * the SHA-256 of everything before it; a reader verifies all of it before it trusts a byte, so a truncated or
 * altered file reads as damaged: one warning line, the file is removed and the work is done again. Writers write a
 * temporary file in the entry's folder and rename it over the entry, so a reader sees a whole entry or none, and two
 * runs storing the same key at once leave one valid entry (the later rename wins). Folder entries (the Taylor
 * terms) keep their own format and checksums; the cache sizes, touches and evicts them as whole folders.
 *
 * <p>The cache holds at most {@code $DIFFRACT_CACHE_MAX_MB} MB (MiB; default {@value #DEFAULT_LIMIT_MB}): after
 * each store, the least recently used entries are removed until it fits. An entry's last use is its modification
 * time, set when it is stored and whenever it is reused, so eviction needs no index file that could itself be
 * damaged, and concurrent runs agree on it.
 */
public final class DiskCache {
    /** The system property that overrides the cache folder (as $DIFFRACT_CACHE does), for programs that embed diffract. */
    public static final String ROOT_PROPERTY = "diffract.cache";
    /** The environment variable that names the cache folder. */
    public static final String ROOT_VARIABLE = "DIFFRACT_CACHE";
    /** The system property that overrides the size limit in MB (as $DIFFRACT_CACHE_MAX_MB does). */
    public static final String LIMIT_PROPERTY = "diffract.cache.maxMb";
    /** The environment variable of the size limit, in MB (2^20 bytes). */
    public static final String LIMIT_VARIABLE = "DIFFRACT_CACHE_MAX_MB";
    /** The size limit when none is set: 2 GiB. */
    public static final long DEFAULT_LIMIT_MB = 2048;
    /** The kinds of entries, one folder each; only these folders are ever sized or evicted. */
    public static final List<String> KINDS = List.of("terms", "baked-tables", "calibration", "reference-maps",
            "rigorous-orders", "order-corrections");
    /** The name ending of an entry file (a folder entry has no ending). */
    public static final String ENTRY_SUFFIX = ".entry";

    private static final String MAGIC = "diffract cache entry 1";
    /** "payload %020d sha256 %64s\n": fixed width, so a reader finds it at the end without a search. */
    private static final int TRAILER_BYTES = 8 + 20 + 8 + 64 + 1;
    private static final int MAX_HEADER_LINE = 1 << 16;

    /** Whether the running command may use the disk ({@code --no-cache} turns it off for one command). */
    private static volatile boolean diskInUse = true;

    private final Path root;
    private final long limitBytes;
    private final Clock clock;

    private DiskCache(Path root, long limitBytes, Clock clock) {
        this.root = root;
        this.limitBytes = limitBytes;
        this.clock = clock;
    }

    /** What an entry holds, written to the payload stream. */
    @FunctionalInterface
    public interface Writer {
        void write(DataOutputStream out) throws IOException;
    }

    /**
     * Reads a payload back; it must read all of it. An exception (or a wrong value it detects itself) makes the entry
     * damaged.
     */
    @FunctionalInterface
    public interface Reader<T> {
        T read(DataInputStream in) throws IOException;
    }

    /**
     * What an entry is made of.
     *
     * @param kind        one of {@link #KINDS}: the folder it lives in
     * @param description every input that changes the entry, in words (one line; kept in the entry's header and
     *                    compared on reading)
     */
    public record Key(String kind, String description) {
        public Key {
            if (!KINDS.contains(kind)) {
                throw new IllegalArgumentException("unknown cache kind " + kind + "; one of " + KINDS);
            }
            if (description.isEmpty() || description.contains("\n") || description.length() > MAX_HEADER_LINE / 2) {
                throw new IllegalArgumentException("a cache key is one non-empty line, got '" + description + "'");
            }
        }

        /** The entry's file name: 128 bits of the key's SHA-256. */
        public String fileName() {
            return sha256Hex((MAGIC + "\n" + kind + "\n" + description).getBytes(StandardCharsets.UTF_8)).substring(0, 32)
                    + ENTRY_SUFFIX;
        }
    }

    /** A damaged entry: the message says what is wrong with it. */
    private static final class Damaged extends Exception {
        private static final long serialVersionUID = 1L;

        Damaged(String message) {
            super(message);
        }
    }

    /**
     * The cache of this command: the user's folder and limit, or a disabled cache when the command was told to
     * leave the disk alone.
     *
     * @throws UserInputException when the size limit is set to something that is not a size
     */
    public static DiskCache user() {
        if (!diskInUse) {
            return disabled();
        }
        return new DiskCache(root(), limitBytes(), Clock.systemUTC());
    }

    /** A cache in {@code root} with the user's limit. */
    public static DiskCache at(Path root) {
        return new DiskCache(root, limitBytes(), Clock.systemUTC());
    }

    /** A cache in {@code root} of at most {@code limitBytes}, whose uses are dated by {@code clock} (tests). */
    public static DiskCache at(Path root, long limitBytes, Clock clock) {
        if (limitBytes < 0) {
            throw new IllegalArgumentException("a cache limit is >= 0 bytes, got " + limitBytes);
        }
        return new DiskCache(root, limitBytes, clock);
    }

    /** A cache that reads and writes nothing. */
    public static DiskCache disabled() {
        return new DiskCache(null, 0, Clock.systemUTC());
    }

    /** Whether work from now on uses the disk cache: the command line turns it off for one command. */
    public static void useDisk(boolean use) {
        diskInUse = use;
    }

    /** Whether work uses the disk cache now ({@link #useDisk}). */
    public static boolean diskInUse() {
        return diskInUse;
    }

    /** The user's cache folder (see the class comment). */
    public static Path root() {
        String property = System.getProperty(ROOT_PROPERTY);
        if (property != null && !property.isBlank()) {
            return Path.of(property);
        }
        String explicit = System.getenv(ROOT_VARIABLE);
        if (explicit != null && !explicit.isBlank()) {
            return Path.of(explicit);
        }
        String xdg = System.getenv("XDG_CACHE_HOME");
        if (xdg != null && !xdg.isBlank()) {
            return Path.of(xdg, "diffract");
        }
        return Path.of(System.getProperty("user.home"), ".cache", "diffract");
    }

    /**
     * The user's size limit in bytes.
     *
     * @throws UserInputException when it is set and is not a whole number of MB from 1
     */
    public static long limitBytes() {
        String property = System.getProperty(LIMIT_PROPERTY);
        String text = property != null && !property.isBlank() ? property : System.getenv(LIMIT_VARIABLE);
        String name = property != null && !property.isBlank() ? "-D" + LIMIT_PROPERTY : LIMIT_VARIABLE;
        if (text == null || text.isBlank()) {
            return DEFAULT_LIMIT_MB << 20;
        }
        try {
            long mb = Long.parseLong(text.trim());
            if (mb >= 1 && mb <= Long.MAX_VALUE >> 20) {
                return mb << 20;
            }
        } catch (NumberFormatException e) {
            // the message below
        }
        throw new UserInputException(name + " must be the disk cache's size limit in MB, a whole number from 1 "
                + "(default " + DEFAULT_LIMIT_MB + "), got '" + text + "'");
    }

    /** Whether this cache reads and writes anything. */
    public boolean enabled() {
        return root != null;
    }

    /** The cache folder (null when disabled). */
    public Path folder() {
        return root;
    }

    /** Where the entry of {@code key} lives (whether or not it exists). */
    public Path file(Key key) {
        requireEnabled();
        return root.resolve(key.kind()).resolve(key.fileName());
    }

    /** The folder of a folder entry of {@code kind} named {@code name} (the caller writes and verifies it). */
    public Path folderEntry(String kind, String name) {
        requireEnabled();
        if (!KINDS.contains(kind) || name.isEmpty() || name.contains("/") || name.contains(FolderLock.TEMPORARY_MARK)) {
            throw new IllegalArgumentException("bad folder entry " + kind + "/" + name);
        }
        return root.resolve(kind).resolve(name);
    }

    /**
     * The value of the entry of {@code key}, verified and read by {@code reader}; null when there is none (or the
     * cache is disabled). A damaged entry is reported as one warning, "{@code FILE is damaged (WHY): REDO}", and
     * removed, and null returned; reading counts as a use.
     *
     * @param redo what the caller does instead, for the warning ("baking the table again")
     */
    public <T> T load(Key key, Reader<T> reader, Reporter reporter, String redo) {
        if (!enabled()) {
            return null;
        }
        Path file = file(key);
        if (!Files.isRegularFile(file)) {
            return null;
        }
        T value;
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            value = read(channel, key, reader);
        } catch (NoSuchFileException e) {
            return null; // evicted or replaced between the look and the open
        } catch (Damaged e) {
            reporter.warn(file + " is damaged (" + e.getMessage() + "): " + redo);
            deleteQuietly(file);
            return null;
        } catch (IOException e) {
            reporter.warn("cannot read " + file + " (" + reason(e) + "): " + redo);
            return null;
        }
        touch(file);
        return value;
    }

    /**
     * Stores an entry: written to a temporary file beside it, renamed over it, dated now, then the cache is trimmed
     * to its limit. A cache that cannot be written is said in one note, not an error: the value is then only in the
     * caller's memory.
     *
     * @param what the value in words, for the notes ("the baked table")
     * @return the entry's file, or empty when the cache is disabled, cannot be written, or the entry alone exceeds
     *         the limit
     */
    public Optional<Path> store(Key key, Writer writer, String what, Reporter reporter) {
        if (!enabled()) {
            return Optional.empty();
        }
        Path file = file(key);
        Path tmp = file.resolveSibling(file.getFileName() + FolderLock.TEMPORARY_MARK + ProcessHandle.current().pid()
                + "-" + System.nanoTime());
        try {
            Files.createDirectories(file.getParent());
            try (OutputStream raw = new BufferedOutputStream(Files.newOutputStream(tmp, StandardOpenOption.CREATE_NEW,
                    StandardOpenOption.WRITE), 1 << 16)) {
                MessageDigest digest = sha256();
                DigestOutputStream digested = new DigestOutputStream(nonClosing(raw), digest);
                digested.write(header(key));
                Counting counting = new Counting(digested);
                DataOutputStream payload = new DataOutputStream(counting);
                writer.write(payload);
                payload.flush();
                raw.write(String.format(Locale.ROOT, "payload %020d sha256 %s\n", counting.count,
                        HexFormat.of().formatHex(digest.digest())).getBytes(StandardCharsets.US_ASCII));
            }
            Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException e) {
            deleteQuietly(tmp);
            reporter.info("cannot write the disk cache " + root + " (" + reason(e) + "): " + what
                    + " is kept in memory only");
            return Optional.empty();
        } catch (RuntimeException | Error e) {
            deleteQuietly(tmp);
            throw e;
        }
        touch(file);
        return trim(file, what, reporter) ? Optional.of(file) : Optional.empty();
    }

    /** Counts {@code entry} (a file or a folder entry) as used now; a cache that cannot be written is left as it is. */
    public void touch(Path entry) {
        if (!enabled()) {
            return;
        }
        try {
            Files.setLastModifiedTime(entry, FileTime.from(clock.instant()));
        } catch (IOException e) {
            // a read-only cache: its entries are still good, only their order of use is not kept
        }
    }

    /**
     * After a folder entry was written: dates it now and trims the cache to its limit.
     *
     * @return whether the entry is still there (false when it alone exceeds the limit)
     */
    public boolean stored(Path folderEntry, String what, Reporter reporter) {
        touch(folderEntry);
        return trim(folderEntry, what, reporter);
    }

    /** One entry as eviction sees it. */
    record Entry(Path path, long bytes, FileTime lastUse) {
    }

    /** Every entry of the cache, least recently used first (ties by path, so the order is the same every time). */
    List<Entry> entries() throws IOException {
        List<Entry> entries = new ArrayList<>();
        for (String kind : KINDS) {
            Path dir = root.resolve(kind);
            if (!Files.isDirectory(dir, LinkOption.NOFOLLOW_LINKS)) {
                continue;
            }
            try (DirectoryStream<Path> children = Files.newDirectoryStream(dir)) {
                for (Path child : children) {
                    String name = child.getFileName().toString();
                    if (name.equals(FolderLock.LOCK_FILE)) {
                        continue;
                    }
                    if (name.contains(FolderLock.TEMPORARY_MARK)) {
                        if (writerIsGone(name)) {
                            deleteTree(child); // a killed writer's leftover
                        }
                        continue;
                    }
                    BasicFileAttributes a;
                    try {
                        a = Files.readAttributes(child, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
                    } catch (NoSuchFileException e) {
                        continue; // removed by another run meanwhile
                    }
                    if (a.isRegularFile() && name.endsWith(ENTRY_SUFFIX)) {
                        entries.add(new Entry(child, a.size(), a.lastModifiedTime()));
                    } else if (a.isDirectory()) {
                        entries.add(new Entry(child, treeBytes(child), a.lastModifiedTime()));
                    }
                }
            }
        }
        entries.sort(Comparator.comparing(Entry::lastUse).thenComparing(e -> e.path().toString()));
        return entries;
    }

    /**
     * Removes the least recently used entries until the cache fits its limit, never {@code keep} unless it alone
     * exceeds the limit. Runs under the cache folder's lock, so two runs trimming at once do not both remove.
     *
     * @return whether {@code keep} is still there
     */
    private boolean trim(Path keep, String what, Reporter reporter) {
        try (FolderLock lock = FolderLock.acquire(root, reporter)) {
            List<Entry> entries = entries();
            long keptBytes = entries.stream().filter(e -> e.path().equals(keep)).mapToLong(Entry::bytes).sum();
            if (keptBytes > limitBytes) {
                remove(keep); // removing others would not make it fit
                reporter.info(String.format(Locale.ROOT, "%s takes %.1f MB, more than the disk cache's limit of %d MB "
                        + "(%s): it is not kept", what, keptBytes / 1048576.0, limitBytes >> 20, LIMIT_VARIABLE));
                return false;
            }
            long total = entries.stream().mapToLong(Entry::bytes).sum();
            long before = total;
            int removed = 0;
            for (Entry e : entries) {
                if (total <= limitBytes) {
                    break;
                }
                if (!e.path().equals(keep) && remove(e.path())) {
                    total -= e.bytes();
                    removed++;
                }
            }
            if (removed > 0) {
                reporter.info(String.format(Locale.ROOT, "the disk cache %s held %.1f MB, over its limit of %d MB (%s):"
                                + " removed the %d least recently used entr%s (%.1f MB)", root, before / 1048576.0,
                        limitBytes >> 20, LIMIT_VARIABLE, removed, removed == 1 ? "y" : "ies",
                        (before - total) / 1048576.0));
            }
            return true;
        } catch (IOException e) {
            return Files.exists(keep); // a cache that cannot be locked or listed: left as it is
        }
    }

    /** Removes an entry: a folder is first renamed away, so no reader finds half of it. */
    private static boolean remove(Path entry) {
        try {
            if (Files.isDirectory(entry, LinkOption.NOFOLLOW_LINKS)) {
                Path away = entry.resolveSibling(entry.getFileName() + FolderLock.TEMPORARY_MARK
                        + ProcessHandle.current().pid() + "-" + System.nanoTime());
                Files.move(entry, away, StandardCopyOption.ATOMIC_MOVE);
                deleteTree(away);
                return true;
            }
            return Files.deleteIfExists(entry);
        } catch (IOException e) {
            return false;
        }
    }

    /** Whether the process that wrote a temporary file ({@code NAME.tmp-PID-NANOS}) has ended. */
    private static boolean writerIsGone(String name) {
        String rest = name.substring(name.indexOf(FolderLock.TEMPORARY_MARK) + FolderLock.TEMPORARY_MARK.length());
        int dash = rest.indexOf('-');
        try {
            long pid = Long.parseLong(dash < 0 ? rest : rest.substring(0, dash));
            return ProcessHandle.of(pid).map(p -> !p.isAlive()).orElse(true);
        } catch (NumberFormatException e) {
            return false; // not one of ours: left alone
        }
    }

    private static long treeBytes(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            return files.mapToLong(p -> {
                try {
                    BasicFileAttributes a = Files.readAttributes(p, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
                    return a.isRegularFile() ? a.size() : 0;
                } catch (IOException e) {
                    return 0;
                }
            }).sum();
        } catch (java.io.UncheckedIOException e) {
            throw e.getCause();
        }
    }

    private static void deleteTree(Path path) {
        try (Stream<Path> files = Files.walk(path)) {
            for (Path p : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        } catch (IOException | java.io.UncheckedIOException e) {
            // what remains is removed by a later trim
        }
    }

    private static void deleteQuietly(Path file) {
        try {
            Files.deleteIfExists(file);
        } catch (IOException e) {
            // a leftover temporary file is removed by a later trim
        }
    }

    private static byte[] header(Key key) {
        return (MAGIC + "\nkind " + key.kind() + "\nkey " + key.description() + "\n\n").getBytes(StandardCharsets.UTF_8);
    }

    /** Verifies the whole file, then reads its payload. */
    private static <T> T read(FileChannel channel, Key key, Reader<T> reader) throws IOException, Damaged {
        long size = channel.size();
        byte[] expectedHeader = header(key);
        if (size < expectedHeader.length + TRAILER_BYTES) {
            throw new Damaged("truncated: " + size + " bytes");
        }
        ByteBuffer trailer = ByteBuffer.allocate(TRAILER_BYTES);
        while (trailer.hasRemaining()) {
            if (channel.read(trailer, size - TRAILER_BYTES + trailer.position()) < 0) {
                throw new Damaged("truncated");
            }
        }
        String tail = new String(trailer.array(), StandardCharsets.US_ASCII);
        if (!tail.startsWith("payload ") || !tail.substring(28).startsWith(" sha256 ") || !tail.endsWith("\n")) {
            throw new Damaged("truncated: it does not end in its checksum");
        }
        long payloadBytes;
        try {
            payloadBytes = Long.parseLong(tail.substring(8, 28));
        } catch (NumberFormatException e) {
            throw new Damaged("its trailer is altered");
        }
        String checksum = tail.substring(36, 100);
        MessageDigest digest = sha256();
        ByteBuffer chunk = ByteBuffer.allocate(1 << 20);
        channel.position(0);
        long left = size - TRAILER_BYTES;
        while (left > 0) {
            chunk.clear().limit((int) Math.min(chunk.capacity(), left));
            int n = channel.read(chunk);
            if (n < 0) {
                throw new Damaged("truncated while reading");
            }
            digest.update(chunk.array(), 0, n);
            left -= n;
        }
        if (!HexFormat.of().formatHex(digest.digest()).equals(checksum)) {
            throw new Damaged("fails its checksum: truncated or altered");
        }
        if (expectedHeader.length + payloadBytes != size - TRAILER_BYTES) {
            throw new Damaged("its header or its length is not this entry's");
        }
        channel.position(0);
        InputStream in = new BufferedInputStream(Channels.newInputStream(channel), 1 << 16);
        byte[] header = in.readNBytes(expectedHeader.length);
        if (!java.util.Arrays.equals(header, expectedHeader)) {
            String first = new String(header, StandardCharsets.UTF_8).lines().findFirst().orElse("");
            throw new Damaged(first.equals(MAGIC) ? "it holds another key" : "not an entry of this version");
        }
        Bounded payload = new Bounded(in, payloadBytes);
        T value;
        try {
            value = reader.read(new DataInputStream(payload));
        } catch (IOException | RuntimeException e) {
            throw new Damaged("its payload does not read: " + reason(e));
        }
        if (payload.left != 0) {
            throw new Damaged("its payload is " + payload.left + " bytes longer than its reader reads");
        }
        return value;
    }

    /** Writes {@code values} as big-endian float32 in blocks (DataOutputStream's one float at a time is slow). */
    public static void writeFloats(DataOutputStream out, float[] values) throws IOException {
        ByteBuffer block = ByteBuffer.allocate(1 << 16);
        for (int i = 0; i < values.length; ) {
            block.clear();
            int n = Math.min(values.length - i, block.capacity() / 4);
            block.asFloatBuffer().put(values, i, n);
            out.write(block.array(), 0, 4 * n);
            i += n;
        }
    }

    /** Reads {@code into.length} floats written by {@link #writeFloats}. */
    public static void readFloats(DataInputStream in, float[] into) throws IOException {
        byte[] bytes = new byte[1 << 16];
        for (int i = 0; i < into.length; ) {
            int n = Math.min(into.length - i, bytes.length / 4);
            in.readFully(bytes, 0, 4 * n);
            ByteBuffer.wrap(bytes, 0, 4 * n).asFloatBuffer().get(into, i, n);
            i += n;
        }
    }

    /** The hex SHA-256 of some bytes (for keys that name content). */
    public static String sha256Hex(byte[] bytes) {
        return HexFormat.of().formatHex(sha256().digest(bytes));
    }

    private void requireEnabled() {
        if (!enabled()) {
            throw new IllegalStateException("the disk cache is disabled");
        }
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every Java runtime", e);
        }
    }

    /** The reason of a failure in words (NIO's messages are often only the path). */
    private static String reason(Exception e) {
        if (e instanceof java.nio.file.AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof java.nio.file.FileSystemException f && f.getReason() != null) {
            return f.getReason();
        }
        if (e instanceof java.io.EOFException) {
            return "it ends early";
        }
        String message = e.getMessage();
        return message == null ? e.getClass().getSimpleName() : message.lines().findFirst().orElse("");
    }

    private static OutputStream nonClosing(OutputStream out) {
        return new FilterOutputStream(out) {
            @Override
            public void write(byte[] b, int off, int len) throws IOException {
                out.write(b, off, len);
            }

            @Override
            public void close() throws IOException {
                flush();
            }
        };
    }

    /** Counts the payload's bytes on their way to the file. */
    private static final class Counting extends FilterOutputStream {
        long count;

        Counting(OutputStream out) {
            super(out);
        }

        @Override
        public void write(int b) throws IOException {
            out.write(b);
            count++;
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            out.write(b, off, len);
            count += len;
        }
    }

    /** The payload's bytes and no more, so a reader cannot run into the trailer. */
    private static final class Bounded extends InputStream {
        private final InputStream in;
        long left;

        Bounded(InputStream in, long bytes) {
            this.in = in;
            this.left = bytes;
        }

        @Override
        public int read() throws IOException {
            if (left <= 0) {
                return -1;
            }
            int b = in.read();
            if (b >= 0) {
                left--;
            }
            return b;
        }

        @Override
        public int read(byte[] b, int off, int len) throws IOException {
            if (left <= 0) {
                return -1;
            }
            int n = in.read(b, off, (int) Math.min(len, left));
            if (n > 0) {
                left -= n;
            }
            return n;
        }
    }
}
