package diffract.viewer;

/** A short message the title shows until {@code untilNanos} ({@link System#nanoTime()} clock). */
public record Notice(String text, long untilNanos) {
    public static Notice forSeconds(String text, double seconds) {
        return new Notice(text, System.nanoTime() + (long) (seconds * 1e9));
    }

    public boolean isShowingAt(long nowNanos) {
        return nowNanos - untilNanos < 0;
    }
}
