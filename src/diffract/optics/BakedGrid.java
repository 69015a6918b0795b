package diffract.optics;

import diffract.optics.spectra.TaylorBound;

/**
 * The sample grid of the BAKED variant's table XYZ(u, v, w): the spectral integral of 004 eq. finalexpression
 * (without the direction-dependent gain factor and shadowing) depends on omega_i and omega_r only through
 * (u, v, w) = -omega_i - omega_r, so it can be tabulated once per patch and settings. Every direction pair above
 * the horizon has |u|, |v| <= 2 and w = -(cos theta_i + cos theta_r) in [-2, 0]; the grid spans that box with
 * samples at both ends: u_i = -2 + 4 i / (n_uv - 1), w_k = -2 + 2 k / (n_w - 1).
 *
 * <p>Resolution: a diffraction order is a Gaussian in (u, v) of standard deviation lambda sigma_f =
 * lambda / (2 pi sigma_s) (the coherence window G of eq. 1.8 mapped back through s = u L / lambda), narrowest at
 * lambda_min. Trilinear interpolation of a Gaussian sampled every h errs by about h^2 / (8 sigma^2) of its peak,
 * so the automatic grid takes {@link #UV_SAMPLES_PER_SIGMA} samples per sigma. Along w the table varies through the
 * phases of texel pairs only: it holds |P|^2, whose terms turn with k w (h(x) - h(x')), up to k_max |w| 2 max|h|,
 * twice the largest Taylor phase x = k_max |w| max|h| of {@link TaylorBound#maxPhase}. Linear interpolation of a
 * cosine sampled every d radians errs by up to d^2 / 8 of its amplitude, so {@link #W_SAMPLES_PER_PAIR_RADIAN} = 2
 * (d = 0.5) holds a pair's term to 3 %; on a measured scan, whose many pairs of unrelated heights all turn at once,
 * half that density leaves CIEDE2000 above 1 under a 20-degree disc (docs/design/filtering.md, section 8).
 */
public record BakedGrid(int uvSamples, int wSamples) {
    /** The largest table edge accepted (GL 3.3 guarantees 3-D textures of 256 only; drivers go to 2048+). */
    public static final int MAX_SAMPLES = 2048;
    /** Samples per sigma of the narrowest order in the automatic (u, v) resolution (error ~ 1/32 of a peak). */
    public static final double UV_SAMPLES_PER_SIGMA = 2.0;
    /** The automatic (u, v) resolution is capped here: 512^2 x w samples x 8 bytes (RGBA16F) = 2 MB per w sample. */
    public static final int MAX_AUTOMATIC_UV_SAMPLES = 512;
    /** Samples along w per radian of the largest phase of a texel pair, k_max |w| 2 max|h|. */
    public static final double W_SAMPLES_PER_PAIR_RADIAN = 2.0;
    public static final double U_MIN = -2.0;
    public static final double U_MAX = 2.0;
    public static final double W_MIN = -2.0;
    public static final double W_MAX = 0.0;

    public BakedGrid {
        if (uvSamples < 2 || wSamples < 2 || uvSamples > MAX_SAMPLES || wSamples > MAX_SAMPLES) {
            throw new IllegalArgumentException("baked grid needs 2.." + MAX_SAMPLES + " samples per axis, got "
                    + uvSamples + " x " + wSamples);
        }
    }

    /** The grid the settings ask for, the automatic resolution where they say 0. */
    public static BakedGrid of(BrdfSettings settings, double maxAbsHeightUm) {
        GpuTableSettings gpu = settings.gpu();
        int uv = gpu.bakedUvSamples() > 0 ? gpu.bakedUvSamples() : automaticUvSamples(settings);
        int w = gpu.bakedWSamples() > 0 ? gpu.bakedWSamples() : automaticWSamples(settings, maxAbsHeightUm);
        return new BakedGrid(uv, w);
    }

    /** The (u, v) sigma of the narrowest order, lambda_min / (2 pi sigma_s) (both in micrometres). */
    public static double narrowestOrderSigma(BrdfSettings settings) {
        return settings.spectral().lambdaMinNm() * 1e-3 * settings.coherenceWindow().sigmaFrequencyPerUm();
    }

    /** The (u, v) samples that resolve the narrowest order with {@link #UV_SAMPLES_PER_SIGMA}, uncapped. */
    public static int uvSamplesToResolve(BrdfSettings settings) {
        double spacing = narrowestOrderSigma(settings) / UV_SAMPLES_PER_SIGMA;
        return (int) Math.ceil((U_MAX - U_MIN) / spacing) + 1;
    }

    /** {@link #uvSamplesToResolve}, capped at {@link #MAX_AUTOMATIC_UV_SAMPLES}. */
    public static int automaticUvSamples(BrdfSettings settings) {
        return Math.min(MAX_AUTOMATIC_UV_SAMPLES, uvSamplesToResolve(settings));
    }

    /** {@link #W_SAMPLES_PER_PAIR_RADIAN} per radian of a pair's largest phase, 2 x, at least 2. */
    public static int automaticWSamples(BrdfSettings settings, double maxAbsHeightUm) {
        double pairPhase = 2 * TaylorBound.maxPhase(settings.spectral().lambdaMinNm(), maxAbsHeightUm);
        return Math.max(2, Math.min(MAX_SAMPLES, (int) Math.ceil(W_SAMPLES_PER_PAIR_RADIAN * pairPhase) + 1));
    }

    /** u (or v) of sample i. */
    public double uv(int i) {
        return U_MIN + (U_MAX - U_MIN) * i / (uvSamples - 1);
    }

    /** w of sample k. */
    public double w(int k) {
        return W_MIN + (W_MAX - W_MIN) * k / (wSamples - 1);
    }

    /** Texels of the table. */
    public long texels() {
        return (long) uvSamples * uvSamples * wSamples;
    }

    /** Bytes of the table at {@code bytesPerTexel} (16 for RGBA32F, 8 for RGBA16F). */
    public long bytes(int bytesPerTexel) {
        return texels() * bytesPerTexel;
    }
}
