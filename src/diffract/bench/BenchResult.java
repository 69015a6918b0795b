package diffract.bench;

/** A measured configuration: median GPU time per frame and its error against the CPU reference. */
public record BenchResult(BenchConfig config, double msPerFrame, MapError error) {
    /** The error the targets and the Pareto front use: mean CIEDE2000 over the lit pixels. */
    public double deltaEMean() {
        return error.mean();
    }
}
