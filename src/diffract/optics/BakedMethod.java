package diffract.optics;

/**
 * A table XYZ(u, v, w) baked once per patch and settings and looked up trilinearly per fragment (after Dhillon and
 * Ghosh 2016, Toisoul and Ghosh 2017): of FLSS under a point light, of the lobes method where the illumination
 * filters. GPU only: on the CPU the method it tabulates is the one to ask.
 *
 * <table>
 *   <caption>Capabilities</caption>
 *   <tr><th>label</th><td>baked</td></tr>
 *   <tr><th>CPU / GPU</th><td>no / {@code baked.frag}</td></tr>
 *   <tr><th>extended lights</th><td>baked in about the normal (the lobes method's table)</td></tr>
 * </table>
 */
final class BakedMethod implements Variant {
    @Override
    public String label() {
        return "baked";
    }

    @Override
    public boolean filtersLight() {
        return true;
    }

    @Override
    public DiffractionBrdf cpuBrdf(BrdfSettings settings, HeightField meanSubtracted, TaylorTerms terms) {
        throw new InvalidSettingException(Quantity.VARIANT, DiffractionBrdf.BAKED_IS_GPU_ONLY);
    }

    @Override
    public DiffractionBrdf cpuBrdfPhaseCentred(BrdfSettings settings, PhaseCentredTerms terms) {
        throw new InvalidSettingException(Quantity.VARIANT, DiffractionBrdf.BAKED_IS_GPU_ONLY);
    }

    @Override
    public String toString() {
        return name();
    }
}
