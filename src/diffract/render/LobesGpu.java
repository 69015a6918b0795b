package diffract.render;

import diffract.jrtr.scenegraph.Material;
import diffract.optics.BrdfSettings;
import diffract.optics.numerics.Covariance2;
import diffract.optics.patches.Direction;
import diffract.optics.numerics.GaussHermite;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.illumination.LightSource;
import diffract.optics.LobeQuadrature;
import diffract.optics.LobeSumTable;
import diffract.optics.lobes.LobeWeightTable;
import diffract.optics.OrderCorrection;
import diffract.optics.settings.OrderWeights;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.Quantity;

/**
 * The lobes method on the GPU ({@code lobes.frag} over {@code lobes_spectrum.glsl}, {@code lobes_footprint.glsl} and
 * {@code lobes_sum.glsl}): the windowed spectrum's lobes averaged over each pixel's footprint and the light.
 *
 * <table>
 *   <caption>Uniforms</caption>
 *   <tr><th>uniform</th><th>from</th></tr>
 *   <tr><td>{@code lobeWeights}, {@code lobeWeightSamples}, {@code lobePhaseStepPerUm},
 *       {@code lobeMaxPhasePerUm}, {@code lobeBlockBounds}, {@code lobeBlockOrder}</td><td>the weight table over the
 *       phase, its blocks' bounds and their texels' order (LobeWeightTable)</td></tr>
 *   <tr><td>{@code lobeSumTable}, {@code lobeSums}, {@code lobeSumCells}, {@code lobeSumCellTexels},
 *       {@code lobeSumNodesPerBox}</td><td>the texel sums, where they apply (LobeSumTable)</td></tr>
 *   <tr><td>{@code lobeSpectralTable}, {@code lobeTablePositions}, {@code lobeDensityMax},
 *       {@code lobeBandWeight}</td><td>the hat-filtered spectral weights and their bounds</td></tr>
 *   <tr><td>{@code lobeCutoff}, {@code lobeNodesPerSigma}, {@code lobeMaxStepNm}, {@code lobeReachSigmas}</td>
 *       <td>the quadrature (LobeQuadrature)</td></tr>
 *   <tr><td>{@code pixelFootprintScale}, {@code lightSigmaRad}, {@code lightHalfAngleRad}, {@code lightDiagonal},
 *       {@code lightRankOne}, {@code lightShifts}, {@code lightShiftCount}</td><td>the pixel filter and the
 *       light</td></tr>
 *   <tr><td>{@code lambdaMinNm}, {@code lambdaMaxNm}, {@code sigmaTexels}</td><td>the band and the window</td></tr>
 * </table>
 */
final class LobesGpu implements GpuMethod {
    /** The shader's light arrays hold this many Gauss-Hermite shifts (lobes_footprint.glsl, the define LIGHT_NODES_MAX). */
    static final int LIGHT_NODES_MAX = 8;

    private static void setLobesLight(Material m, Covariance2 c, LobeQuadrature q) {
        double[] split = c.isDiagonal() ? new double[] {c.xx(), c.yy(), 1, 0, 0} : c.diagonalPlusRankOne();
        m.setVec2("lightDiagonal", (float) split[0], (float) split[1]);
        m.setVec3("lightRankOne", (float) (split[4] * split[2] * split[2]),
                (float) (split[4] * split[2] * split[3]), (float) (split[4] * split[3] * split[3]));
        float[] shifts = new float[3 * LIGHT_NODES_MAX];
        int count = 0;
        if (split[4] > 0) {
            double sigma = Math.sqrt(split[4]);
            double[] nodes = GaussHermite.nodes(q.lightNodes());
            double[] weights = GaussHermite.weights(q.lightNodes());
            for (int k = 0; k < nodes.length; k++) {
                shifts[3 * k] = (float) (sigma * nodes[k] * split[2]);
                shifts[3 * k + 1] = (float) (sigma * nodes[k] * split[3]);
                shifts[3 * k + 2] = (float) weights[k];
            }
            count = nodes.length;
        }
        m.setFloatArray("lightShifts", shifts).setInt("lightShiftCount", count);
    }

    /** Its march and wavelength nodes notice loops the GL ended early (lobes_spectrum.glsl's spectrumTruncated). */
    @Override
    public boolean reportsShortPixels() {
        return true;
    }

    /** The cutoff scaled to what a picture shown at {@code exposure} displays ({@link LobeQuadrature#shownAt}). */
    @Override
    public void setExposure(Material m, BrdfSettings settings, double exposure) {
        m.setFloat("lobeCutoff", (float) settings.lobes().shownAt(exposure).cutoff());
    }

    /**
     * The lobes method's uniforms ({@code lobes_spectrum.glsl}, {@code lobes_footprint.glsl}): spectral weights,
     * quadrature, pixel filter, the light's size and, until {@link #setLight} places it, the light of normal
     * incidence. The shader sums whole texels only: a patch whose window keeps pairs of texels at the quadrature's
     * threshold is refused.
     */
    @Override
    public void setUniforms(Material m, DiffractionTextures textures, BrdfSettings settings) {
        LobeQuadrature q = settings.lobes();
        LobeQuadrature.wholeTexelsRefusal(settings, textures.extentXUm(), textures.extentYUm()).ifPresent(why -> {
            throw new InvalidSettingException(Quantity.COHERENCE_LENGTH, why + "; render it with the lobes variant on "
                    + "the CPU, with flss or the reference, with a longer coherence length or a smaller patch");
        });
        LightSource light = settings.illumination().light();
        LobeWeightTable table = textures.lobes().weightTable(settings, q);
        m.setTexture("lobeWeights", textures.lobes().weights(settings, q))
                .setInt("lobeWeightSamples", table.samples())
                .setFloat("lobePhaseStepPerUm", (float) table.stepPerUm())
                .setFloat("lobeMaxPhasePerUm", (float) table.maxPhasePerUm())
                .setFloat("lobeCutoff", (float) q.cutoff());
        m.setTexture("lobeBlockBounds", textures.lobes().blockBounds(settings, q))
                .setTexture("lobeBlockOrder", textures.lobes().blockOrder(settings, q));
        java.util.Optional<LobeSumTable> sums = textures.lobes().sumTable(settings, q);
        java.util.Optional<OrderCorrection> orders = textures.lobes().orders();
        // a texel sum adds the lobes of many orders under one weight: the corrected lobes are summed one by one
        m.setTexture("lobeSumTable", textures.lobes().sums(settings, q))
                .setInt("lobeSums", sums.isPresent() && orders.isEmpty() ? 1 : 0)
                .setVec2("lobeSumCells", sums.map(LobeSumTable::cellsX).orElse(0),
                        sums.map(LobeSumTable::cellsY).orElse(0))
                .setFloat("lobeSumCellTexels", sums.map(LobeSumTable::cellTexels).orElse(1))
                .setFloat("lobeSumNodesPerBox", (float) q.sumNodesPerBox());
        m.setTexture("lobeSpectralTable", textures.lobes().spectralTable(settings.spectral()))
                .setInt("lobeTablePositions", textures.lobes().spectralTablePositions(settings.spectral()))
                .setTexture("lobeDensityMax", textures.lobes().densityMax(settings.spectral()))
                .setFloat("lobeBandWeight", (float) textures.lobes().bandWeight(settings.spectral()))
                .setFloat("lobeNodesPerSigma", (float) q.nodesPerSigma())
                .setFloat("lobeMaxStepNm", (float) q.maxStepNm())
                .setFloat("lobeReachSigmas", (float) q.reachSigmas())
                .setFloat("pixelFootprintScale", DiffractionMaterials.pixelFootprintScale(settings))
                .setFloat("lightSigmaRad", (float) light.sigmaRad())
                .setFloat("lambdaMinNm", (float) settings.spectral().lambdaMinNm())
                .setFloat("lambdaMaxNm", (float) settings.spectral().lambdaMaxNm());
        if (settings.rigorous().orders() == OrderWeights.RIGOROUS) {
            OrderCorrection ratios = orders.orElseThrow(() -> new IllegalStateException(
                    "the settings ask for the rigorous orders and the textures hold none"));
            m.setTexture("orderRatios", textures.lobes().orderRatios())
                    .setFloat("orderLargestRatio", (float) ratios.largest())
                    .setVec3("orderNodes", ratios.nodes(), ratios.alphas(), ratios.betas())
                    .setInt("orderMaxOrder", ratios.maxOrder())
                    .setInt("orderRidges", ratios.ridges())
                    .setInt("orderAxis", ratios.axisIndex())
                    .setFloat("orderFirstNm", (float) ratios.firstNm())
                    .setFloat("orderStepNm", (float) OrderCorrection.STEP_NM)
                    .setFloat("orderAngleStep", (float) OrderCorrection.ANGLE_STEP);
        }
        setLobesLight(m, light.uvCovariance(Direction.fromSphericalDeg(0, 0)), q);
        if (averagesOverDisc(settings)) {
            m.setFloat("lightHalfAngleRad", (float) light.halfAngleRad());
        }
        GpuMethod.gaussianWindow(m, textures, settings);
    }

    /** Whether it averages over a disc light (lobes_footprint.glsl's LIGHT_DISC, DiscFootprint). */
    static boolean averagesOverDisc(BrdfSettings settings) {
        return settings.illumination().light().isDisc();
    }

    /**
     * {@code LOBES_BOX} where a BRDF map's pixels are boxes (lobes_footprint.glsl compiles one footprint, not both),
     * {@code LIGHT_DISC} under a disc light.
     */
    @Override
    public void addDefines(java.util.Map<String, String> defines, BrdfSettings settings, boolean brdfMap) {
        if (brdfMap && settings.illumination().pixelFilter() == PixelFilter.BOX) {
            defines.put("LOBES_BOX", "1");
        }
        if (averagesOverDisc(settings)) {
            defines.put("LIGHT_DISC", "1");
        }
        if (settings.rigorous().orders() == OrderWeights.RIGOROUS) {
            defines.put("RIGOROUS_ORDERS", "1");
        }
    }

    /**
     * Its table's samples ({@code baked_lobes.frag}) average over their cell of the table (the box of
     * {@link #bakeSettings}, {@code LOBES_BOX}) and the light the table holds ({@code setTableCell}; a point under a
     * disc, {@link BakedDisc#heldBy}): the defines of its BRDF map's program.
     */
    @Override
    public String bakeFragmentPath() {
        return "diffraction/baked_lobes.frag";
    }

    /**
     * Every sample of its table averages over the sample's cell: the pixel box. A table is a function of
     * -omega_i - omega_r alone and holds the scalar orders (the rigorous ones depend on omega_i besides).
     */
    @Override
    public BrdfSettings bakeSettings(BrdfSettings settings) {
        return settings.with(b -> b.pixelFilter(PixelFilter.BOX)
                .rigorous(settings.rigorous().withOrders(OrderWeights.SCALAR)));
    }

    /** Environment lights wider than it sums read its baked table (ENVIRONMENT_TABLE). */
    @Override
    public boolean tablesWideEnvironmentLights() {
        return true;
    }

    /** The settings' light as its (u, v) covariance at omega_i, which every pixel of a BRDF map shares. */
    @Override
    public void setLight(Material brdfMap, Direction wi, BrdfSettings settings) {
        setLobesLight(brdfMap, settings.illumination().light().uvCovariance(wi), settings.lobes());
    }

}
