package diffract.viewer;

/** A background precompute of Taylor terms 0..{@code targetOrder} under way, {@code fraction} in [0, 1] done. */
public record PrecomputeProgress(int targetOrder, double fraction) {
    public PrecomputeProgress {
        fraction = Math.max(0.0, Math.min(1.0, fraction));
    }

    public int percent() {
        return (int) Math.floor(100.0 * fraction);
    }
}
