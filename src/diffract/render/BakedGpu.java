package diffract.render;

/**
 * The baked table on the GPU ({@code baked.frag}): the table of FLSS or of the lobes method looked up per pixel. The
 * table is one of the shared textures ({@link DiffractionMaterials}); its program also holds FLSS's bake pass and
 * declares FLSS's uniforms, which it takes from {@link FlssGpu}.
 */
final class BakedGpu extends FlssGpu {
    /** A filtered table under an environment reads its lights from tables spread by each light. */
    @Override
    public boolean readsSkyTables() {
        return true;
    }
}
