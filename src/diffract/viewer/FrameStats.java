package diffract.viewer;

import java.util.concurrent.atomic.AtomicLong;

/**
 * Frames drawn and the time per frame, written by the render thread and read by the title updater and tests.
 * The time is wall-clock from the start of a frame to the end of its GPU work (the renderer waits with glFinish),
 * smoothed exponentially so the title does not flicker.
 */
public final class FrameStats {
    private static final double SMOOTHING = 0.3;
    private final AtomicLong frames = new AtomicLong();
    private volatile double smoothedMs = Double.NaN;
    private volatile double lastMs = Double.NaN;

    void record(double ms) {
        lastMs = ms;
        double previous = smoothedMs;
        smoothedMs = Double.isNaN(previous) ? ms : previous + SMOOTHING * (ms - previous);
        frames.incrementAndGet();
    }

    public long frameCount() {
        return frames.get();
    }

    /** Smoothed milliseconds per frame; NaN before the first frame. */
    public double msPerFrame() {
        return smoothedMs;
    }

    public double lastFrameMs() {
        return lastMs;
    }
}
