package diffract.jrtr.gl;

import com.jogamp.opengl.GL2ES2;
import com.jogamp.opengl.GL2GL3;
import com.jogamp.opengl.GL3;

import java.util.Arrays;

/**
 * Measures GPU time with timer queries ({@code GL_TIME_ELAPSED}): the time the GPU spent on the commands of
 * each frame, not the CPU time to issue them. Needs the GL context current.
 */
public final class GpuTimer {
    /** Fewer frames give a median too noisy to compare. */
    public static final int MIN_FRAMES = 10;

    private final GL3 gl;

    public GpuTimer(GL3 gl) {
        this.gl = gl;
        int[] bits = new int[1];
        gl.glGetQueryiv(GL2ES2.GL_TIME_ELAPSED, GL2GL3.GL_QUERY_COUNTER_BITS, bits, 0);
        if (bits[0] == 0) {
            throw new UnsupportedOperationException("this GL implementation has no GL_TIME_ELAPSED timer");
        }
    }

    /** Milliseconds of each of {@code frames} frames, after {@code warmupFrames} unmeasured ones. */
    public double[] measureMs(Runnable drawFrame, int warmupFrames, int frames) {
        if (frames < 1 || warmupFrames < 0) {
            throw new IllegalArgumentException("need frames >= 1 and warmupFrames >= 0");
        }
        for (int i = 0; i < warmupFrames; i++) {
            drawFrame.run();
        }
        gl.glFinish();
        int[] queries = new int[frames];
        gl.glGenQueries(frames, queries, 0);
        try {
            // queries of consecutive frames are issued back to back and read at the end, so reading one result
            // never stalls the next frame's submission
            for (int i = 0; i < frames; i++) {
                gl.glBeginQuery(GL2ES2.GL_TIME_ELAPSED, queries[i]);
                drawFrame.run();
                gl.glEndQuery(GL2ES2.GL_TIME_ELAPSED);
            }
            double[] ms = new double[frames];
            long[] nanos = new long[1];
            for (int i = 0; i < frames; i++) {
                gl.glGetQueryObjectui64v(queries[i], GL2ES2.GL_QUERY_RESULT, nanos, 0);
                ms[i] = nanos[0] / 1e6;
            }
            GLErrors.check(gl, "measuring GPU time");
            return ms;
        } finally {
            gl.glDeleteQueries(frames, queries, 0);
        }
    }

    /** Median milliseconds per frame over {@code frames} (at least {@value #MIN_FRAMES}) measured frames. */
    public double measureMedianMs(Runnable drawFrame, int warmupFrames, int frames) {
        if (frames < MIN_FRAMES) {
            throw new IllegalArgumentException("need at least " + MIN_FRAMES + " frames for a median, got " + frames);
        }
        return median(measureMs(drawFrame, warmupFrames, frames));
    }

    static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }
}
