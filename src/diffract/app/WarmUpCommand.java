package diffract.app;

import picocli.CommandLine.Command;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.concurrent.Callable;
import java.util.stream.Stream;

/**
 * {@code diffract warm-up} (hidden): runs a tiny patch, precompute, cached rerun and BRDF map in a temporary folder,
 * so that the launcher can record the classes a typical run loads into a class-data-sharing archive right after a
 * build. Later starts map those classes instead of loading them (about 0.6 -> 0.4 s for a cached precompute).
 * It leaves out the reference map: with the classes of a reference map's run in the archive, Java 17 ran the
 * reference map five times slower (42.7 s against 8.2 s for the 64^2 map of docs/measurements/pieces.sh's patch, same output).
 */
@Command(name = "warm-up", hidden = true)
final class WarmUpCommand implements Callable<Integer> {
    @Override
    public Integer call() throws Exception {
        Path dir = Files.createTempDirectory("diffract-warm-up");
        try {
            String patch = dir.resolve("p.gsf").toString();
            String terms = dir.resolve("terms").toString();
            int code = Main.execute("patch", "blazed", "--periods", "2", "--samples-per-period", "8", "--rows", "2", "-o", patch);
            code |= Main.execute("precompute", "--patch", patch, "--terms", "3", "-o", terms);
            code |= Main.execute("precompute", "--patch", patch, "--terms", "3", "-o", terms);
            code |= Main.execute("brdfmap", "--patch", patch, "--theta-i", "20", "--variant", "flss", "--terms", "3",
                    "--terms-dir", terms, "--size", "4", "-o", dir.resolve("m.png").toString());
            return code;
        } finally {
            try (Stream<Path> files = Files.walk(dir)) {
                files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
    }
}
