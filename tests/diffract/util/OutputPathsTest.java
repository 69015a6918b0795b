package diffract.util;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The output checks on their own, and the atomic write's refusal to replace what is not a regular file (a rename
 * over a device node replaces the node; as root nothing else stops it).
 */
class OutputPathsTest {
    @TempDir
    Path dir;

    static final Path DEV_NULL = Path.of("/dev/null");

    private static String refusal(Runnable check) {
        UserInputException e = assertThrows(UserInputException.class, check::run);
        assertEquals(1, e.getMessage().lines().count(), e.getMessage());
        return e.getMessage();
    }

    private static void assertCharacterDevice(Path path) {
        assumeTrue(Files.exists(path), path + " is missing here");
        assertEquals("a character device", OutputPaths.kind(path), path + " is still a device");
    }

    @Test
    void aDeviceIsRefusedAsAFileAndAsAFolder() {
        assertCharacterDevice(DEV_NULL);
        assertEquals("-o /dev/null is a character device, not a regular file; name a file to write, e.g. map.png",
                refusal(() -> OutputPaths.requireWritableFile(DEV_NULL, "-o", "map.png", ".png")));
        assertEquals("--to /dev/null is a character device, not a folder; name a folder to write into",
                refusal(() -> OutputPaths.requireWritableFolder(DEV_NULL, "--to")));
        assertCharacterDevice(DEV_NULL);
    }

    @Test
    void aFifoIsRefused() throws Exception {
        Path fifo = SpecialFiles.fifo(dir.resolve("map.png"));
        assertEquals("-o " + fifo + " is a named pipe (fifo), not a regular file; name a file to write, e.g. map.png",
                refusal(() -> OutputPaths.requireWritableFile(fifo, "-o", "map.png", ".png")));
        assertEquals("a named pipe (fifo)", OutputPaths.kind(fifo));
    }

    @Test
    void theKernelsFileSystemsAreRefused() {
        assumeTrue(Files.isDirectory(Path.of("/proc/self")), "no /proc here");
        assertEquals("-o /proc/x.png: /proc holds the kernel's own files (proc), not files to write; choose another"
                        + " place", refusal(() -> OutputPaths.requireWritableFile(Path.of("/proc/x.png"), "-o",
                "map.png", ".png")));
        assertTrue(refusal(() -> OutputPaths.requireWritableFolder(Path.of("/proc/terms"), "-o"))
                .startsWith("-o /proc/terms: /proc holds the kernel's own files"));
        assertFalse(Files.exists(Path.of("/proc/x.png")));
    }

    @Test
    void aFolderIsRefusedAsAFile() {
        assertEquals("-o " + dir + " is a folder; name the file to write, e.g. " + dir.resolve("map.png"),
                refusal(() -> OutputPaths.requireWritableFile(dir, "-o", "map.png", ".png")));
    }

    @Test
    void twoOutputsOnOnePathAreRefused() {
        Path a = dir.resolve("m.exr");
        Path b = dir.resolve("sub").resolve("..").resolve(".").resolve("m.exr");
        assertEquals("-o " + a + " and --exr " + b + " are the same file; give each output its own name",
                refusal(() -> OutputPaths.require(OutputPaths.file("-o", a, "map.png", ".png", ".exr"),
                        OutputPaths.file("--pfm", null, "map.pfm", ".pfm"),
                        OutputPaths.file("--exr", b, "map.exr", ".exr"))));
        OutputPaths.require(OutputPaths.file("-o", a, "map.png", ".png", ".exr"),
                OutputPaths.file("--exr", dir.resolve("n.exr"), "map.exr", ".exr"));
    }

    @Test
    void aLinkToAnotherOutputIsTheSameFile() throws IOException {
        Path map = Files.writeString(dir.resolve("m.exr"), "x");
        Path link = Files.createSymbolicLink(dir.resolve("l.exr"), map);
        assertEquals("-o " + map + " and --exr " + link + " are the same file; give each output its own name",
                refusal(() -> OutputPaths.require(OutputPaths.file("-o", map, "map.png", ".png", ".exr"),
                        OutputPaths.file("--exr", link, "map.exr", ".exr"))));
    }

    @Test
    void anExtensionTheCommandCannotWriteIsRefusedWithTheOnesItCan() {
        Path jpg = dir.resolve("x.jpg");
        assertEquals("-o " + jpg + ": cannot write .jpg files; -o writes .png or .exr (e.g. map.png)",
                refusal(() -> OutputPaths.requireWritableFile(jpg, "-o", "map.png", ".png", ".exr")));
        Path bare = dir.resolve("x");
        assertEquals("--pfm " + bare + ": the name has no extension; --pfm writes .pfm (e.g. map.pfm)",
                refusal(() -> OutputPaths.requireWritableFile(bare, "--pfm", "map.pfm", ".pfm")));
        OutputPaths.requireWritableFile(dir.resolve("X.PNG"), "-o", "map.png", ".png"); // any case
        assertEquals(".png, .gif or .exr", OutputPaths.orList(List.of(".png", ".gif", ".exr")));
    }

    @Test
    void theProbeLeavesNothingBehind() throws IOException {
        OutputPaths.require(OutputPaths.file("-o", dir.resolve("a/b/m.png"), "map.png", ".png"),
                OutputPaths.folder("--save", dir.resolve("c")));
        try (Stream<Path> left = Files.list(dir)) {
            assertEquals(List.of(), left.toList(), "no probe, no folder made");
        }
    }

    @Test
    void theAtomicWriteNeverReplacesASpecialFile() throws Exception {
        assertCharacterDevice(DEV_NULL);
        FileSystemException onDevice = assertThrows(FileSystemException.class,
                () -> ImageFiles.writePng(DEV_NULL, new float[3], 1, 1, 3));
        assertEquals("/dev/null", onDevice.getFile());
        assertTrue(onDevice.getReason().contains("a character device, not a regular file"), onDevice.getReason());
        assertCharacterDevice(DEV_NULL);

        Path fifo = SpecialFiles.fifo(dir.resolve("turn.gif"));
        assertThrows(FileSystemException.class,
                () -> AnimatedGif.write(fifo, List.of(new float[3]), 1, 1, 80));
        assertEquals("a named pipe (fifo)", OutputPaths.kind(fifo));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(fifo), files.toList(), "no temporary file left");
        }
    }

    /** A failed write names the file asked for, never its temporary sibling. */
    @Test
    void aFailedWriteNamesTheFileNotItsTemporaryName() {
        Path below = dir.resolve("a-file").resolve("m.png");
        IOException e = assertThrows(IOException.class, () -> {
            Files.writeString(dir.resolve("a-file"), "x");
            ImageFiles.writePfm(below, new float[1], 1, 1, 1);
        });
        assertFalse(e.getMessage().contains(FolderLock.TEMPORARY_MARK), e.getMessage());
        assumeTrue(Files.isDirectory(Path.of("/proc/self")), "no /proc here");
        IOException proc = assertThrows(IOException.class,
                () -> ImageFiles.writePng(Path.of("/proc/x.png"), new float[3], 1, 1, 3));
        assertFalse(proc.getMessage().contains(FolderLock.TEMPORARY_MARK), proc.getMessage());
        assertTrue(proc.getMessage().contains("/proc/x.png"), proc.getMessage());
    }
}
