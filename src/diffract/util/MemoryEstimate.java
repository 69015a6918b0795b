package diffract.util;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * What a piece of work will hold in the Java heap at its peak, part by part, checked before the work starts
 * against what the heap may still grow to ({@link Runtime#maxMemory()} less what is in use now): work that cannot
 * fit is refused at once, with the estimate and a way out, instead of dying of OutOfMemoryError after minutes.
 * The parts are the large arrays the work allocates (each estimator documents its own); small objects are left out.
 */
public final class MemoryEstimate {
    private static final double GB = 1e9;

    /** One large allocation: what it is and its bytes. */
    public record Part(String what, long bytes) {
    }

    private final List<Part> parts = new ArrayList<>();

    private MemoryEstimate() {
    }

    public static MemoryEstimate empty() {
        return new MemoryEstimate();
    }

    public static MemoryEstimate of(String what, long bytes) {
        return new MemoryEstimate().plus(what, bytes);
    }

    /** Adds a part (ignored when {@code bytes} is 0). */
    public MemoryEstimate plus(String what, long bytes) {
        if (bytes < 0) {
            throw new IllegalArgumentException("negative memory estimate for " + what + ": " + bytes);
        }
        if (bytes > 0) {
            parts.add(new Part(what, bytes));
        }
        return this;
    }

    public MemoryEstimate plus(MemoryEstimate other) {
        parts.addAll(other.parts);
        return this;
    }

    public List<Part> parts() {
        return List.copyOf(parts);
    }

    /** The sum of the parts, saturating at Long.MAX_VALUE. */
    public long bytes() {
        long sum = 0;
        for (Part p : parts) {
            sum = sum > Long.MAX_VALUE - p.bytes() ? Long.MAX_VALUE : sum + p.bytes();
        }
        return sum;
    }

    /** What the heap may still grow by now: its maximum less what is in use. */
    public static long availableHeapBytes() {
        Runtime runtime = Runtime.getRuntime();
        long max = runtime.maxMemory();
        if (max == Long.MAX_VALUE) {
            return Long.MAX_VALUE;
        }
        return max - (runtime.totalMemory() - runtime.freeMemory());
    }

    public static long maxHeapBytes() {
        return Runtime.getRuntime().maxMemory();
    }

    /**
     * Refuses the work when it does not fit the heap.
     *
     * @param task   what would run, e.g. "the reference map of a 2048x2048 patch"
     * @param wayOut how to need less, e.g. "crop the patch or use --variant flss"
     * @throws UserInputException with the estimate, the heap's limit and both ways out (less work, a larger heap)
     */
    public void require(String task, String wayOut) {
        require(task, wayOut, availableHeapBytes(), maxHeapBytes());
    }

    /** As {@link #require(String, String)} against a given heap (tests). */
    public void require(String task, String wayOut, long availableBytes, long maxBytes) {
        if (bytes() <= availableBytes) {
            return;
        }
        long heapGiB = suggestedHeapGiB();
        long machineBytes = physicalMemoryBytes();
        if (machineBytes > 0 && bytes() > machineBytes) {
            throw new UserInputException(String.format(Locale.ROOT, "%s needs about %s of memory (%s), more than this"
                    + " machine's %s; %s", task, size(bytes()), describeParts(), size(machineBytes), wayOut));
        }
        throw new UserInputException(String.format(Locale.ROOT, "%s needs about %s of memory (%s), but the Java heap"
                        + " can grow by only %s (limit %s); %s, or give Java a larger heap: DIFFRACT_JAVA_OPTS=-Xmx%dg"
                        + " ./diffract ... (java -Xmx%dg -jar ...)", task, size(bytes()), describeParts(),
                size(Math.max(0, availableBytes)), size(maxBytes), wayOut, heapGiB, heapGiB));
    }

    /** The machine's physical memory, or 0 when the runtime does not say. */
    static long physicalMemoryBytes() {
        try {
            java.lang.management.OperatingSystemMXBean os = java.lang.management.ManagementFactory
                    .getOperatingSystemMXBean();
            if (os instanceof com.sun.management.OperatingSystemMXBean sun) {
                return sun.getTotalMemorySize();
            }
        } catch (RuntimeException | LinkageError e) {
            // not every runtime has the extension: no comparison then
        }
        return 0;
    }

    /** "5.8 GB", "12 MB" or "5.0 TB". */
    public static String size(long bytes) {
        if (bytes >= 1000 * GB) {
            return String.format(Locale.ROOT, "%.1f TB", bytes / (1000 * GB));
        }
        if (bytes >= GB) {
            return String.format(Locale.ROOT, "%.1f GB", bytes / GB);
        }
        return String.format(Locale.ROOT, "%.0f MB", Math.max(1.0, bytes / 1e6));
    }

    /** "terms 1.0 GB + map 12 MB". */
    public String describeParts() {
        List<String> out = new ArrayList<>();
        for (Part p : parts) {
            out.add(p.what() + " " + size(p.bytes()));
        }
        return String.join(" + ", out);
    }

    /** The estimate plus a quarter (the JVM's own and everything small), rounded up to whole GiB. */
    long suggestedHeapGiB() {
        double gib = bytes() * 1.25 / (1L << 30);
        return Math.max(1, (long) Math.ceil(gib + 0.5));
    }
}
