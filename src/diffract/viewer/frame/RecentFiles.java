package diffract.viewer.frame;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The files last opened or saved in the viewer's frame, newest first, at most {@link #MAX}, kept in a text file (one
 * path a line) so that the next start lists them. A file that cannot be read or written only loses the list.
 */
public final class RecentFiles {
    public static final int MAX = 8;

    private final Path store;

    /** The list kept in {@code store} (null: kept for this run only). */
    public RecentFiles(Path store) {
        this.store = store;
    }

    /**
     * The user's list: {@code $XDG_CONFIG_HOME/diffract/recent-files} (else {@code ~/.config/...}), or the file the
     * system property {@code diffract.recentFiles} names.
     */
    public static RecentFiles user() {
        String property = System.getProperty("diffract.recentFiles");
        if (property != null) {
            return new RecentFiles(Path.of(property));
        }
        String config = System.getenv("XDG_CONFIG_HOME");
        Path base = config != null && !config.isBlank() ? Path.of(config)
                : Path.of(System.getProperty("user.home"), ".config");
        return new RecentFiles(base.resolve("diffract").resolve("recent-files"));
    }

    private final List<Path> inMemory = new ArrayList<>();

    /** The files, newest first, those that no longer exist left out. */
    public synchronized List<Path> list() {
        List<Path> all = new ArrayList<>();
        if (store != null && Files.isRegularFile(store)) {
            try {
                for (String line : Files.readAllLines(store, StandardCharsets.UTF_8)) {
                    if (!line.isBlank()) {
                        all.add(Path.of(line.strip()));
                    }
                }
            } catch (IOException | RuntimeException e) {
                all.clear();
            }
        } else {
            all.addAll(inMemory);
        }
        return all.stream().filter(Files::exists).distinct().limit(MAX).toList();
    }

    /** Puts {@code file} first. */
    public synchronized void add(Path file) {
        Path absolute = file.toAbsolutePath().normalize();
        List<Path> next = new ArrayList<>();
        next.add(absolute);
        for (Path p : list()) {
            if (!p.equals(absolute) && next.size() < MAX) {
                next.add(p);
            }
        }
        inMemory.clear();
        inMemory.addAll(next);
        if (store == null) {
            return;
        }
        try {
            Files.createDirectories(store.toAbsolutePath().getParent());
            Files.write(store, next.stream().map(Path::toString).toList(), StandardCharsets.UTF_8);
        } catch (IOException | RuntimeException e) {
            System.err.println("diffract: cannot keep the recent files in " + store + ": " + e.getMessage());
        }
    }
}
