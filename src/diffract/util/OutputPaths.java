package diffract.util;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Checks, before any work, that a command will be able to write where it was told to: a result lost after minutes
 * of computing because the output names a folder, or a folder nobody may write in, is refused at the start instead.
 * Files are written under a temporary name in their folder and renamed (see {@link ImageFiles#writeAtomically}),
 * so what must be writable is the folder; missing folders are created, so the nearest existing one is checked.
 * Each message names the option ({@code label}) so the user knows what to change.
 */
public final class OutputPaths {
    private OutputPaths() {
    }

    /**
     * A file to write.
     *
     * @param label   how the user named it, e.g. "-o"
     * @param example a file name to suggest when {@code file} is a folder, e.g. "map.png"
     */
    public static void requireWritableFile(Path file, String label, String example) {
        if (Files.isDirectory(file)) {
            throw new UserInputException(label + " " + file + " is a folder; name the file to write, e.g. "
                    + file.resolve(example));
        }
        Path parent = file.toAbsolutePath().normalize().getParent();
        if (parent != null) {
            requireCreatableFolder(parent, label + " " + file);
        }
    }

    /** A folder to write into (created if missing). */
    public static void requireWritableFolder(Path dir, String label) {
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw new UserInputException(label + " " + dir + " is a file, not a folder; name a folder to write into");
        }
        requireCreatableFolder(dir.toAbsolutePath().normalize(), label + " " + dir);
    }

    /** {@code dir} exists and is writable, or its nearest existing ancestor is a writable folder. */
    private static void requireCreatableFolder(Path dir, String what) {
        Path existing = dir;
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        if (existing == null) {
            return; // nothing of the path exists, not even a root: let the write say what is wrong
        }
        if (!Files.isDirectory(existing)) {
            throw new UserInputException("cannot write " + what + ": " + existing + " is a file, not a folder");
        }
        if (!Files.isWritable(existing)) {
            throw new UserInputException("cannot write " + what + ": the folder " + existing
                    + " is not writable; choose another place");
        }
    }
}
