package diffract.util;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Set;

/**
 * Checks, before any work, that a command will be able to write where it was told to: a result lost after minutes
 * of computing because the output names a folder, a device, a kernel file or a format the command cannot write is
 * refused at the start instead. Files are written under a temporary name in their folder and renamed (see
 * {@link ImageFiles#writeAtomically}), so what must take a new file is the folder: a temporary file is created in
 * it and deleted again, because permissions alone do not tell (root may "write" in /proc, which takes no files).
 * Missing folders are created by the writer, so the nearest existing one is probed. Each message names the option
 * ({@code label}) so the user knows what to change.
 *
 * <pre>{@code
 * OutputPaths.require(OutputPaths.file("-o", output, "map.png", ".png", ".exr"),
 *         OutputPaths.file("--pfm", pfm, "map.pfm", ".pfm")); // a null path is an output not asked for
 * }</pre>
 */
public final class OutputPaths {
    /** The kernel's own file systems: their entries are not files to put a result in, whatever permissions say. */
    private static final Set<String> KERNEL_FILE_SYSTEMS = Set.of("proc", "sysfs", "devtmpfs", "devpts", "debugfs",
            "tracefs", "securityfs", "cgroup", "cgroup2", "configfs", "pstore", "bpf", "efivarfs", "fusectl",
            "mqueue", "binfmt_misc");
    /** Where those are mounted on every Linux, for when the file store's type cannot be read. */
    private static final List<Path> KERNEL_FOLDERS = List.of(Path.of("/proc"), Path.of("/sys"));

    private OutputPaths() {
    }

    /**
     * One thing a command writes.
     *
     * @param label      how the user named it, e.g. "-o"
     * @param path       where; null when the output was not asked for
     * @param example    a file name to suggest (files only), e.g. "map.png"
     * @param extensions the endings the command can write, lower case with the dot; null for a folder
     */
    public record Output(String label, Path path, String example, List<String> extensions) {
        boolean folder() {
            return extensions == null;
        }
    }

    /** A file the command writes, in one of {@code extensions} (e.g. ".png", ".exr"). */
    public static Output file(String label, Path path, String example, String... extensions) {
        if (extensions.length == 0) {
            throw new IllegalArgumentException("a file output needs the extensions it can have");
        }
        return new Output(label, path, example, Arrays.asList(extensions));
    }

    /** A folder the command writes into (created if missing). */
    public static Output folder(String label, Path path) {
        return new Output(label, path, null, null);
    }

    /**
     * Refuses, with one line naming the option, outputs that name the same file, and any output that is a folder
     * where a file is meant (or the reverse), a device, pipe or socket, a path in the kernel's file systems, a file
     * of an extension the command cannot write, or a place whose folder takes no new file.
     */
    public static void require(Output... outputs) {
        List<Output> given = new ArrayList<>();
        for (Output o : outputs) {
            if (o != null && o.path() != null) {
                given.add(o);
            }
        }
        requireDistinct(given);
        Set<Path> probed = new HashSet<>();
        for (Output o : given) {
            if (o.folder()) {
                checkFolder(o, probed);
            } else {
                checkFile(o, probed);
            }
        }
    }

    /** A single file to write; see {@link #require}. */
    public static void requireWritableFile(Path file, String label, String example, String... extensions) {
        require(file(label, file, example, extensions));
    }

    /** A single folder to write into (created if missing); see {@link #require}. */
    public static void requireWritableFolder(Path dir, String label) {
        require(folder(label, dir));
    }

    private static void requireDistinct(List<Output> outputs) {
        int n = outputs.size();
        Path[] normalised = new Path[n];
        boolean[] exists = new boolean[n];
        for (int i = 0; i < n; i++) {
            normalised[i] = outputs.get(i).path().toAbsolutePath().normalize();
            exists[i] = Files.exists(outputs.get(i).path());
        }
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                if (normalised[i].equals(normalised[j])
                        || exists[i] && exists[j] && sameFile(outputs.get(i).path(), outputs.get(j).path())) {
                    Output a = outputs.get(i);
                    Output b = outputs.get(j);
                    throw new UserInputException(a.label() + " " + a.path() + " and " + b.label() + " " + b.path()
                            + " are the same file; give each output its own name");
                }
            }
        }
    }

    /** Links and other spellings of one existing file. */
    private static boolean sameFile(Path a, Path b) {
        try {
            return Files.isSameFile(a, b);
        } catch (IOException e) {
            return false;
        }
    }

    private static void checkFile(Output o, Set<Path> probed) {
        Path file = o.path();
        String named = o.label() + " " + file;
        if (Files.isDirectory(file)) {
            throw new UserInputException(named + " is a folder; name the file to write, e.g. "
                    + file.resolve(o.example()));
        }
        if (Files.exists(file) && !Files.isRegularFile(file)) {
            throw new UserInputException(named + " is " + kind(file) + ", not a regular file; name a file to write,"
                    + " e.g. " + o.example());
        }
        Path absolute = file.toAbsolutePath().normalize();
        requireOrdinaryFileSystem(absolute, named);
        requireExtension(o, named);
        Path parent = absolute.getParent();
        if (parent != null) {
            requireFolderTakesFiles(parent, named, probed);
        }
    }

    private static void checkFolder(Output o, Set<Path> probed) {
        Path dir = o.path();
        String named = o.label() + " " + dir;
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw new UserInputException(named + " is " + kind(dir) + ", not a folder; name a folder to write into");
        }
        Path absolute = dir.toAbsolutePath().normalize();
        requireOrdinaryFileSystem(absolute, named);
        requireFolderTakesFiles(absolute, named, probed);
    }

    private static void requireExtension(Output o, String named) {
        Path name = o.path().getFileName();
        String lower = name == null ? "" : name.toString().toLowerCase(Locale.ROOT);
        if (o.extensions().stream().anyMatch(lower::endsWith)) {
            return;
        }
        int dot = lower.lastIndexOf('.');
        String has = dot > 0 ? "cannot write " + lower.substring(dot) + " files" : "the name has no extension";
        throw new UserInputException(named + ": " + has + "; " + o.label() + " writes " + orList(o.extensions())
                + " (e.g. " + o.example() + ")");
    }

    /** ".png", ".png or .exr", ".png, .gif or .exr". */
    static String orList(List<String> items) {
        if (items.size() == 1) {
            return items.get(0);
        }
        return String.join(", ", items.subList(0, items.size() - 1)) + " or " + items.get(items.size() - 1);
    }

    /** What kind of file system object a path that is neither a regular file nor a folder is, in words. */
    static String kind(Path path) {
        if (Files.isRegularFile(path)) {
            return "a file";
        }
        if (Files.isDirectory(path)) {
            return "a folder";
        }
        try {
            int mode = ((Number) Files.getAttribute(path, "unix:mode")).intValue();
            switch (mode & 0170000) {
                case 0020000:
                    return "a character device";
                case 0060000:
                    return "a block device";
                case 0010000:
                    return "a named pipe (fifo)";
                case 0140000:
                    return "a socket";
                default:
                    break;
            }
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | ClassCastException e) {
            // no unix view here: the general word below
        }
        return "a special file";
    }

    /** Refuses a path in /proc, /sys or another of the kernel's file systems. */
    private static void requireOrdinaryFileSystem(Path absolute, String named) {
        Path existing = nearestExisting(absolute);
        if (existing == null) {
            return;
        }
        Path real;
        try {
            real = existing.toRealPath();
        } catch (IOException e) {
            real = existing;
        }
        String type = null;
        try {
            type = Files.getFileStore(real).type();
        } catch (IOException | RuntimeException e) {
            // unknown: the folders below still tell
        }
        Path where = null;
        for (Path kernel : KERNEL_FOLDERS) {
            if (real.startsWith(kernel) || absolute.startsWith(kernel)) {
                where = kernel;
            }
        }
        if (where == null && type != null && KERNEL_FILE_SYSTEMS.contains(type)) {
            where = real;
        }
        if (where != null) {
            throw new UserInputException(named + ": " + where + " holds the kernel's own files"
                    + (type != null ? " (" + type + ")" : "") + ", not files to write; choose another place");
        }
    }

    /**
     * {@code dir}, or its nearest existing ancestor when it is to be created, is a folder that takes a new file: a
     * temporary file is created there and deleted (once per folder and call).
     */
    private static void requireFolderTakesFiles(Path dir, String named, Set<Path> probed) {
        Path existing = nearestExisting(dir);
        if (existing == null) {
            return; // nothing of the path exists, not even a root: let the write say what is wrong
        }
        if (!Files.isDirectory(existing)) {
            throw new UserInputException("cannot write " + named + ": " + existing + " is " + kind(existing)
                    + ", not a folder");
        }
        if (!Files.isWritable(existing)) {
            throw new UserInputException("cannot write " + named + ": the folder " + existing
                    + " is not writable; choose another place");
        }
        if (!probed.add(existing)) {
            return;
        }
        Path probe;
        try {
            probe = Files.createTempFile(existing, ".diffract-probe" + FolderLock.TEMPORARY_MARK, "");
        } catch (IOException | RuntimeException e) {
            throw new UserInputException("cannot write " + named + ": the folder " + existing
                    + " takes no new file (" + reason(e) + "); choose another place", e);
        }
        try {
            Files.deleteIfExists(probe);
        } catch (IOException e) {
            // a probe left behind carries the temporary mark, which the folder's next writer removes
        }
    }

    private static String reason(Exception e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileSystemException f && f.getReason() != null) {
            return f.getReason();
        }
        return Objects.requireNonNullElse(e.getMessage(), e.getClass().getSimpleName());
    }

    private static Path nearestExisting(Path absolute) {
        Path existing = absolute;
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        return existing;
    }
}
