package diffract.app.options;

import diffract.util.DiskCache;
import picocli.CommandLine.Option;

import java.util.List;

/**
 * {@code --no-cache}, shared by the commands that use the disk cache ({@link DiskCache}: Taylor terms, baked tables,
 * calibrations of {@code auto}, reference maps): the command neither reads nor writes it, and computes everything
 * afresh, in memory. It applies to the one command: {@code Main.execute} switches the cache by whether the
 * command it runs was given the flag (parsing alone switches nothing), and back when the command ends.
 */
public final class CacheOption {
    public static final String FLAG = "--no-cache";

    @Option(names = FLAG) boolean noCache;

    /** The option as given, for a command that runs another: {@code --no-cache}, or nothing. */
    public List<String> arguments() {
        return noCache ? List.of(FLAG) : List.of();
    }
}
