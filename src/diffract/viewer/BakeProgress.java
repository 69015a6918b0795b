package diffract.viewer;

/** A background bake of the baked variant's table under way, {@code fraction} in [0, 1] done. */
public record BakeProgress(double fraction) {
    public BakeProgress {
        fraction = Math.max(0.0, Math.min(1.0, fraction));
    }

    public int percent() {
        return (int) Math.floor(100.0 * fraction);
    }
}
