package diffract.render;

import diffract.colour.HatFilteredSpectrum;
import diffract.jrtr.textures.FloatTexture1D;
import diffract.jrtr.textures.FloatTextureArray;
import diffract.optics.BrdfSettings;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.LobeQuadrature;
import diffract.optics.LobeSumTable;
import diffract.optics.lobes.LobeWeightTable;
import diffract.optics.OrderCorrection;
import diffract.optics.settings.Quantity;
import diffract.optics.settings.SpectralSettings;

import java.util.function.BiFunction;

/**
 * The lobes method's tables of one patch's terms ({@link DiffractionTextures#lobes}), each made and uploaded on first
 * use: the hat-filtered spectral weights and their range maxima, the weight table |T_m(k w)|^2 with its block bounds
 * and block orders, and the texel sums where they apply.
 */
public final class LobeTextures {
    /** Makes the weight table from the patch's terms: (lambda_min nm, tolerance) -> table. */
    private final BiFunction<Double, Double, LobeWeightTable> weightSource;
    private final double extentXUm;
    private final double extentYUm;
    private HatFilteredSpectrum spectrum;
    private FloatTexture1D spectralTable;
    private LobeWeightTable weightTable;
    private FloatTextureArray weights;
    private FloatTextureArray blockBounds;
    private FloatTextureArray blockOrder;
    private FloatTexture1D densityMax;
    private LobeSumTable sumTable;
    private FloatTextureArray sums;
    /** The rigorous orders' ratios ({@link OrderCorrection}), or null: the scalar orders. */
    private OrderCorrection orders;
    private diffract.jrtr.textures.FloatTexture3D orderRatios;

    LobeTextures(BiFunction<Double, Double, LobeWeightTable> weightSource, double extentXUm, double extentYUm) {
        this.weightSource = weightSource;
        this.extentXUm = extentXUm;
        this.extentYUm = extentYUm;
    }

    /**
     * The lobes method's spectral weights ({@link HatFilteredSpectrum}) for the settings' band, made on first use:
     * one 1-D RGBA32F texture, level-major.
     */
    public synchronized FloatTexture1D spectralTable(SpectralSettings spectral) {
        if (spectralTable == null) {
            spectrum = new HatFilteredSpectrum(spectral.lambdaMinNm(), spectral.lambdaMaxNm(),
                    spectral.normalisation());
            spectralTable = new FloatTexture1D(spectrum.rgba());
        }
        return spectralTable;
    }

    /** The blocks' orders of {@link #weights}' texels ({@link LobeWeightTable#orderLayer}); one RG32F layer. */
    public synchronized FloatTextureArray blockOrder(BrdfSettings settings, LobeQuadrature quadrature) {
        LobeWeightTable table = weightTable(settings, quadrature);
        if (blockOrder == null) {
            blockOrder = new FloatTextureArray(table.blockCols() * LobeWeightTable.BLOCK,
                    table.blockRows() * LobeWeightTable.BLOCK, java.util.List.of(table.orderLayer()),
                    FloatTextureArray.Precision.FLOAT32);
        }
        return blockOrder;
    }

    /**
     * The range maxima of {@link #spectralTable}'s weights per nanometre (HatFilteredSpectrum.rangeMaxRgba), for
     * the lobes' cutoff.
     */
    public synchronized FloatTexture1D densityMax(SpectralSettings spectral) {
        spectralTable(spectral);
        if (densityMax == null) {
            densityMax = new FloatTexture1D(spectrum.rangeMaxRgba());
        }
        return densityMax;
    }

    /** HatFilteredSpectrum.bandWeight of {@link #spectralTable}'s weights, for the lobes' cutoff. */
    public synchronized double bandWeight(SpectralSettings spectral) {
        spectralTable(spectral);
        return spectrum.bandWeight();
    }

    /** Entries per level of {@link #spectralTable}. */
    public synchronized int spectralTablePositions(SpectralSettings spectral) {
        spectralTable(spectral);
        return spectrum.positions();
    }

    /**
     * The lobes method's weight table ({@link LobeWeightTable}: |T_m(k w)|^2 per texel over the phase, and its
     * bounds) for the settings' shortest wavelength and the quadrature's tolerance, made on first use from the same
     * terms as the CPU's (the settings' Taylor order, or the phase-centred expansion); one RG32F texture array.
     */
    public synchronized FloatTextureArray weights(BrdfSettings settings, LobeQuadrature quadrature) {
        LobeWeightTable table = weightTable(settings, quadrature);
        if (weights == null) {
            weights = new FloatTextureArray(table.cols(), table.rows(), table.layers(),
                    FloatTextureArray.Precision.FLOAT32);
        }
        return weights;
    }

    /** The block bounds of {@link #weights} ({@link LobeWeightTable#blockLayers}); one RG32F texture array. */
    public synchronized FloatTextureArray blockBounds(BrdfSettings settings, LobeQuadrature quadrature) {
        LobeWeightTable table = weightTable(settings, quadrature);
        if (blockBounds == null) {
            blockBounds = new FloatTextureArray(table.blockCols(), table.blockRows(), table.blockLayers(),
                    FloatTextureArray.Precision.FLOAT32);
        }
        return blockBounds;
    }

    /**
     * The lobes method's texel sums ({@link LobeSumTable}) over its weight table, made on first use where they apply
     * to these textures' extent under the settings ({@link LobeSumTable#applies}); empty elsewhere. One RGBA32F texture
     * array, filtered linearly within a layer.
     */
    public synchronized java.util.Optional<LobeSumTable> sumTable(BrdfSettings settings, LobeQuadrature quadrature) {
        if (!LobeSumTable.applies(settings.coherenceWindow(), quadrature, extentXUm, extentYUm)) {
            return java.util.Optional.empty();
        }
        if (sumTable == null) {
            sumTable = new LobeSumTable(weightTable(settings, quadrature),
                    settings.coherenceWindow().sigmaTexels(extentXUm),
                    settings.coherenceWindow().sigmaTexels(extentYUm));
        }
        return java.util.Optional.of(sumTable);
    }

    /**
     * The texture of {@link #sumTable}, or one texel of 0 where the sums do not apply (the sampler still needs a
     * texture of its type).
     */
    public synchronized FloatTextureArray sums(BrdfSettings settings, LobeQuadrature quadrature) {
        java.util.Optional<LobeSumTable> table = sumTable(settings, quadrature);
        if (sums != null && table.isPresent() != (sums.width() > 1)) {
            throw new IllegalStateException("these textures hold the lobes' texel sums for other settings; make new "
                    + "textures");
        }
        if (sums == null) {
            sums = table
                    .map(t -> FloatTextureArray.rgba(t.width(), t.height(), t.layers()))
                    .orElseGet(() -> FloatTextureArray.rgba(1, 1, java.util.List.of(new float[4])))
                    .linear();
        }
        return sums;
    }

    /** Makes the lobes take the rigorous orders' ratios ({@link diffract.optics.settings.OrderWeights#RIGOROUS}). */
    public synchronized void useOrders(OrderCorrection table) {
        if (orders != null && orders != table) {
            throw new IllegalStateException("these textures hold another table of rigorous orders; make new textures");
        }
        orders = table;
    }

    /** The rigorous orders' table, where the lobes take it. */
    public synchronized java.util.Optional<OrderCorrection> orders() {
        return java.util.Optional.ofNullable(orders);
    }

    /**
     * The rigorous orders' ratios as a 3-D texture of their table's layout (x the wavelength, y the direction cosine
     * across the ridges, z the order times |beta| along them), trilinear, made on first use: the red channel holds the
     * ratio.
     */
    public synchronized diffract.jrtr.textures.FloatTexture3D orderRatios() {
        if (orders == null) {
            throw new IllegalStateException("no table of rigorous orders: the lobes take the scalar ones");
        }
        if (orderRatios == null) {
            float[] ratio = orders.textureData();
            float[] rgb = new float[3 * ratio.length];
            for (int i = 0; i < ratio.length; i++) {
                rgb[3 * i] = ratio[i];
            }
            orderRatios = new diffract.jrtr.textures.FloatTexture3D(orders.nodes(), orders.alphas(),
                    (2 * orders.maxOrder() + 1) * orders.betas(), rgb,
                    diffract.jrtr.textures.FloatTexture3D.Precision.FLOAT32);
        }
        return orderRatios;
    }

    /** The table behind {@link #weights}. */
    public synchronized LobeWeightTable weightTable(BrdfSettings settings, LobeQuadrature quadrature) {
        if (quadrature.weightTolerance() == 0) {
            throw new InvalidSettingException(Quantity.LOBE_QUADRATURE, "the lobes shader reads a table of the lobe "
                    + "weights: a weight tolerance of 0 (the coefficients at every wavelength) is for the CPU only");
        }
        if (weightTable != null && (weightTable.tolerance() != quadrature.weightTolerance()
                || weightTable.lambdaMinNm() != settings.spectral().lambdaMinNm())) {
            throw new IllegalStateException("these textures hold the lobe weights for tolerance "
                    + weightTable.tolerance() + " from " + weightTable.lambdaMinNm() + " nm; make new textures");
        }
        if (weightTable == null) {
            weightTable = weightSource.apply(settings.spectral().lambdaMinNm(), quadrature.weightTolerance());
        }
        return weightTable;
    }
}
