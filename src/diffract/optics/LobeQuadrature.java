package diffract.optics;

import diffract.colour.HatFilteredSpectrum;
import diffract.optics.lobes.GaussianLobes;
import diffract.optics.lobes.LobeWeightTable;
import diffract.optics.numerics.GaussHermite;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.windows.CoherenceWindow;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The accuracy knobs of the lobes method ({@link LobeSpectrum}, {@code lobes.frag}), a group of {@link BrdfSettings};
 * docs/design/filtering.md measures each. Every knob has one range, checked here ({@link Quantity#LOBE_QUADRATURE}).
 *
 * @param pairThreshold  with the window fixed at the DFT's origin, texel pairs m != m' are summed while their window
 *                       weight exp(-|m - m'|^2_sigma / 4) is at least this (relative to the product of their
 *                       coefficients); in (0, 1]. The GPU sums whole texels only: it needs a threshold that keeps no
 *                       pair for the patch. The window averaged over its position keeps no pair whatever this says
 * @param nodesPerSigma  wavelength nodes per standard deviation of a lobe's passage through the footprint (the
 *                       width, in nm, of its erf edges or Gaussian profile); &gt; 0
 * @param maxStepNm      the widest node spacing: 1, 2, 4, 8 or 16 nm (the hat-filtered spectral weights), or any
 *                       spacing below 1 nm (point weights): bounds how coarsely the spectrum is followed across a
 *                       wide lobe
 * @param reachSigmas    a lobe is summed where it comes within this many standard deviations of the footprint
 * @param weightStepNm   the lobe's slowly varying factors (its weight W_c(k w), and the footprint's average along
 *                       an axis the lobe does not move on) are evaluated every this many nanometres of its passage and
 *                       at its ends, linearly interpolated between; 0 = at every node
 * @param lightNodes     Gauss-Hermite nodes along the part of a light's covariance that a BRDF-map pixel's box
 *                       cannot average analytically (lights off the axes of the patch), 1..8
 * @param cutoff         a lobe is skipped, before its weight is read, when it can add at most this much to a pixel's
 *                       tristimulus values (D65 white = 1, before the gain factor): its weight table's bound over the
 *                       lobe's phases times the spectral weights' bound over its wavelengths times a bound on its
 *                       footprint average summed over its nodes (docs/design/filtering.md, "The march and the cutoff");
 *                       in [0, 1e-2], 0 keeps every lobe; a quadrature {@link #shownAt shown} at an exposure holds
 *                       the cutoff scaled to it
 * @param weightTolerance the interpolation error of the tabulated lobe weights W_m(k w) ({@link LobeWeightTable}),
 *                       relative to a texel's largest weight, in [0, 1e-2]; 0 sums the coefficients at every
 *                       evaluation instead (CPU only: the shader reads the table)
 * @param sumNodesPerBox where the lobes are at least as wide as a texel's cell ({@link LobeSumTable#applies}: scans
 *                       wider than about two thirds of the coherence length) and the light is not a disc, the texels
 *                       under the footprint are summed from {@link LobeSumTable} at wavelength nodes spaced so that a
 *                       lobe's passage through the footprint (the box's width and the lobe's) is seen by this many
 *                       nodes; in [0, 16], 0 marches over the lobes one by one everywhere
 * @param askedCutoff    the cutoff as asked, for a picture shown at {@link #CUTOFF_EXPOSURE} or dimmer: the one that
 *                       {@link #shownAt} scales, so that a quadrature shown at one exposure and then at another holds
 *                       the second's cutoff, not both scalings compounded; at least {@code cutoff}
 */
public record LobeQuadrature(double pairThreshold, double nodesPerSigma, double maxStepNm, double reachSigmas,
                             double weightStepNm, int lightNodes, double cutoff, double weightTolerance,
                             double sumNodesPerBox, double askedCutoff) {
    public static final double DEFAULT_CUTOFF = 3e-6;
    public static final double DEFAULT_WEIGHT_TOLERANCE = 1e-4;
    public static final double DEFAULT_SUM_NODES_PER_BOX = 2;
    public static final LobeQuadrature DEFAULT = new LobeQuadrature(1e-4, 0.67, 8, 4.0, 8, 3);

    /** With the default cutoff and weight table. */
    public LobeQuadrature(double pairThreshold, double nodesPerSigma, double maxStepNm, double reachSigmas,
                          double weightStepNm, int lightNodes) {
        this(pairThreshold, nodesPerSigma, maxStepNm, reachSigmas, weightStepNm, lightNodes, DEFAULT_CUTOFF,
                DEFAULT_WEIGHT_TOLERANCE);
    }

    /** As asked: shown at no exposure above {@link #CUTOFF_EXPOSURE}. */
    public LobeQuadrature(double pairThreshold, double nodesPerSigma, double maxStepNm, double reachSigmas,
                          double weightStepNm, int lightNodes, double cutoff, double weightTolerance,
                          double sumNodesPerBox) {
        this(pairThreshold, nodesPerSigma, maxStepNm, reachSigmas, weightStepNm, lightNodes, cutoff, weightTolerance,
                sumNodesPerBox, cutoff);
    }

    /** With the default sums over texels for wide scans. */
    public LobeQuadrature(double pairThreshold, double nodesPerSigma, double maxStepNm, double reachSigmas,
                          double weightStepNm, int lightNodes, double cutoff, double weightTolerance) {
        this(pairThreshold, nodesPerSigma, maxStepNm, reachSigmas, weightStepNm, lightNodes, cutoff, weightTolerance,
                DEFAULT_SUM_NODES_PER_BOX);
    }

    /**
     * The exposure at which the default cutoff is a third of a display step (docs/measurements/bench/cutoff.md): shown brighter, a
     * skipped lobe is that much brighter on the display.
     */
    public static final double CUTOFF_EXPOSURE = 30;

    /**
     * This quadrature for a picture shown at {@code exposure} (XYZ times it, white at 1): the cutoff holds what a
     * skipped lobe can show at {@link #CUTOFF_EXPOSURE}, so a brighter picture scales it down by
     * CUTOFF_EXPOSURE / exposure; a picture shown at that exposure or dimmer keeps it. A dim map shown at the
     * brightness of its brightest diffracted pixel (a point light's narrow orders, exposures of 10^4) would otherwise
     * lose lobes that it shows at a tenth of white. The scaling starts from the cutoff as asked, whatever exposure
     * this quadrature was shown at before (a viewer's exposure keys, a scene drawn for its exposure and then shown at
     * it): showing it at the same exposure twice changes nothing.
     */
    public LobeQuadrature shownAt(double exposure) {
        double shown = exposure > CUTOFF_EXPOSURE ? askedCutoff * CUTOFF_EXPOSURE / exposure : askedCutoff;
        if (shown == cutoff) {
            return this;
        }
        return new LobeQuadrature(pairThreshold, nodesPerSigma, maxStepNm, reachSigmas, weightStepNm, lightNodes,
                shown, weightTolerance, sumNodesPerBox, askedCutoff);
    }

    /**
     * The knobs by name, as the command line ({@code --lobe-quadrature K=V}) and scene files ({@code lobeQuadrature})
     * give them: the record's components, the cutoff as asked.
     */
    public static final List<String> KNOBS = List.of("pairThreshold", "nodesPerSigma", "maxStepNm", "reachSigmas",
            "weightStepNm", "lightNodes", "cutoff", "weightTolerance", "sumNodesPerBox");

    /** Every knob's value by its name ({@link #KNOBS}), the cutoff as asked. */
    public Map<String, Double> knobs() {
        Map<String, Double> knobs = new LinkedHashMap<>();
        knobs.put("pairThreshold", pairThreshold);
        knobs.put("nodesPerSigma", nodesPerSigma);
        knobs.put("maxStepNm", maxStepNm);
        knobs.put("reachSigmas", reachSigmas);
        knobs.put("weightStepNm", weightStepNm);
        knobs.put("lightNodes", (double) lightNodes);
        knobs.put("cutoff", askedCutoff);
        knobs.put("weightTolerance", weightTolerance);
        knobs.put("sumNodesPerBox", sumNodesPerBox);
        return knobs;
    }

    /**
     * These knobs with those {@code changes} names ({@link #KNOBS}) replaced, each value checked as the constructor
     * checks it; a name that is no knob, or a fractional number of light nodes, is refused.
     */
    public LobeQuadrature withKnobs(Map<String, Double> changes) {
        Map<String, Double> k = knobs();
        for (Map.Entry<String, Double> change : changes.entrySet()) {
            if (!k.containsKey(change.getKey())) {
                throw invalid("no knob '" + change.getKey() + "'; the knobs are " + String.join(", ", KNOBS));
            }
            k.put(change.getKey(), change.getValue());
        }
        double lightNodes = k.get("lightNodes");
        if (lightNodes != Math.rint(lightNodes)) {
            throw invalid("the light nodes must be a whole number, got " + lightNodes);
        }
        return new LobeQuadrature(k.get("pairThreshold"), k.get("nodesPerSigma"), k.get("maxStepNm"),
                k.get("reachSigmas"), k.get("weightStepNm"), (int) lightNodes, k.get("cutoff"),
                k.get("weightTolerance"), k.get("sumNodesPerBox"));
    }

    /** The same knobs, with the texel sums at this many nodes per lobe's passage (0: never summed). */
    public LobeQuadrature withSumNodesPerBox(double nodes) {
        return new LobeQuadrature(pairThreshold, nodesPerSigma, maxStepNm, reachSigmas, weightStepNm, lightNodes,
                cutoff, weightTolerance, nodes, askedCutoff);
    }

    public LobeQuadrature {
        if (!(pairThreshold > 0 && pairThreshold <= 1)) {
            throw invalid("the pair threshold must be in (0, 1], got " + pairThreshold);
        }
        if (!(nodesPerSigma > 0) || !(nodesPerSigma <= 100)) {
            throw invalid("the nodes per sigma must be in (0, 100], got " + nodesPerSigma);
        }
        if (!(maxStepNm > 0 && maxStepNm < 1)) {
            try {
                HatFilteredSpectrum.levelOf(maxStepNm);
            } catch (IllegalArgumentException e) {
                throw invalid("the widest node spacing must be 1, 2, 4, 8 or 16 nm, or below 1 nm, got " + maxStepNm);
            }
        }
        if (!(reachSigmas >= 2 && reachSigmas <= 10)) {
            throw invalid("the reach must be 2..10 standard deviations, got " + reachSigmas);
        }
        if (!(weightStepNm >= 0 && weightStepNm <= 400)) {
            throw invalid("the weight step must be in [0, 400] nm (0 = every node), got " + weightStepNm);
        }
        if (lightNodes < 1 || lightNodes > GaussHermite.MAX_NODES) {
            throw invalid("the light nodes must be 1.." + GaussHermite.MAX_NODES + ", got " + lightNodes);
        }
        if (!(cutoff >= 0 && cutoff <= 1e-2)) {
            throw invalid("the cutoff must be in [0, 1e-2] of white, got " + cutoff);
        }
        if (!(askedCutoff >= cutoff && askedCutoff <= 1e-2)) {
            throw invalid("the cutoff as asked must be in [cutoff, 1e-2] of white, got " + askedCutoff);
        }
        if (!(weightTolerance >= 0 && weightTolerance <= 1e-2)) {
            throw invalid("the weight tolerance must be in [0, 1e-2] (0: no table), got " + weightTolerance);
        }
        if (!(sumNodesPerBox >= 0 && sumNodesPerBox <= 16)) {
            throw invalid("the sum's nodes per passage must be in [0, 16] (0: march over the lobes), got "
                    + sumNodesPerBox);
        }
    }

    private static InvalidSettingException invalid(String what) {
        return new InvalidSettingException(Quantity.LOBE_QUADRATURE, Quantity.LOBE_QUADRATURE.words() + ": " + what);
    }

    /**
     * K = floor(2 sigma sqrt(ln(1 / threshold))): the largest texel offset |m - m'| along an axis of sigma_f =
     * {@code sigmaTexels} whose pair weight exp(-K^2 / (4 sigma^2)) reaches the threshold (0: whole texels only).
     */
    public static int pairRadius(double sigmaTexels, double pairThreshold) {
        return GaussianLobes.pairRadius(sigmaTexels, pairThreshold);
    }

    /**
     * Why a shader that sums whole texels (lobes.frag) cannot draw a patch of this extent under these settings: the
     * window, fixed at the DFT's origin, keeps pairs of texels above the pair threshold (sigma_f too wide); empty when
     * it can (always with the window averaged over its position, which keeps no pair).
     */
    public static java.util.Optional<String> wholeTexelsRefusal(BrdfSettings settings, double extentXUm,
                                                                double extentYUm) {
        CoherenceWindow window = settings.coherenceWindow();
        LobeQuadrature q = settings.lobes();
        if (window.averaged() || pairRadius(window.sigmaTexels(extentXUm), q.pairThreshold()) == 0
                && pairRadius(window.sigmaTexels(extentYUm), q.pairThreshold()) == 0) {
            return java.util.Optional.empty();
        }
        return java.util.Optional.of(String.format(java.util.Locale.ROOT, "the lobes shader sums whole texels, but "
                + "this %.1f x %.1f um patch at a %s um coherence length has sigma_f = %.2f texels: with the window "
                + "fixed at the DFT's origin texel pairs weigh more than the pair threshold %.0e (the window averaged "
                + "over its position, the default, keeps no pairs)", extentXUm, extentYUm,
                InvalidSettingException.number(settings.illumination().coherenceLengthUm()),
                window.sigmaTexels(Math.max(extentXUm, extentYUm)), q.pairThreshold()));
    }
}
