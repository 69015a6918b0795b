package diffract.util;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentMap;
import java.util.concurrent.locks.ReentrantLock;

/**
 * Exclusive right to write a folder, between processes (an OS file lock on {@value #LOCK_FILE} inside it) and
 * between threads of this process (the OS lock belongs to the whole process, so threads queue on a lock of their
 * own first). Writers of a folder hold it while they check, write and rename, so two writers end in one
 * consistent folder; whatever temporary files it holds then belong to no live writer and are removed
 * ({@link #removeStaleTemporaries}). The OS releases the lock of a killed process. Reentrant per thread.
 */
public final class FolderLock implements AutoCloseable {
    /** The lock file, left in the folder (an empty file). */
    public static final String LOCK_FILE = ".lock";
    /** What every temporary file of diffract has in its name ({@link ImageFiles#writeAtomically}). */
    public static final String TEMPORARY_MARK = ".tmp-";

    private static final ConcurrentMap<Path, Holder> HOLDERS = new ConcurrentHashMap<>();

    /** The per-folder state of this process. */
    private static final class Holder {
        final ReentrantLock threads = new ReentrantLock();
        FileChannel channel;
        FileLock fileLock;
    }

    private final Path dir;
    private final Holder holder;
    private boolean closed;

    private FolderLock(Path dir, Holder holder) {
        this.dir = dir;
        this.holder = holder;
    }

    /**
     * Creates {@code dir} if needed and waits for its lock; says once (through {@code reporter}) that it waits when
     * another process holds it.
     *
     * @throws IOException when the folder or its lock file cannot be created (e.g. a read-only place)
     */
    public static FolderLock acquire(Path dir, Reporter reporter) throws IOException {
        Files.createDirectories(dir);
        Path key = dir.toRealPath();
        Holder holder = HOLDERS.computeIfAbsent(key, k -> new Holder());
        if (!holder.threads.tryLock()) {
            reporter.info("waiting for another writer of " + dir + " to finish");
            holder.threads.lock();
        }
        try {
            if (holder.threads.getHoldCount() == 1) {
                FileChannel channel = FileChannel.open(key.resolve(LOCK_FILE), StandardOpenOption.CREATE,
                        StandardOpenOption.WRITE);
                try {
                    FileLock lock = channel.tryLock();
                    if (lock == null) {
                        reporter.info("waiting for another process writing " + dir + " to finish");
                        lock = channel.lock();
                    }
                    holder.channel = channel;
                    holder.fileLock = lock;
                } catch (IOException | RuntimeException e) {
                    channel.close();
                    throw e;
                }
            }
            return new FolderLock(dir, holder);
        } catch (IOException | RuntimeException e) {
            holder.threads.unlock();
            throw e;
        }
    }

    /**
     * Deletes the temporary files ({@value #TEMPORARY_MARK} in the name) directly in the folder: with the lock
     * held, no writer is writing them, so they are what a killed or failed writer left behind.
     *
     * @return how many were removed
     */
    public int removeStaleTemporaries() throws IOException {
        int removed = 0;
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, p -> p.getFileName().toString()
                .contains(TEMPORARY_MARK) && Files.isRegularFile(p))) {
            for (Path p : files) {
                if (Files.deleteIfExists(p)) {
                    removed++;
                }
            }
        }
        return removed;
    }

    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            if (holder.threads.getHoldCount() == 1 && holder.channel != null) {
                try {
                    holder.fileLock.release();
                } finally {
                    holder.channel.close();
                    holder.channel = null;
                    holder.fileLock = null;
                }
            }
        } finally {
            holder.threads.unlock();
        }
    }
}
