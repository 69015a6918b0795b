package diffract.viewer;

/**
 * Where the window's refinement stands ({@link RefiningRenderer}): what it draws and how far it got. Immutable;
 * the render loop publishes a new one after each tile, the title and tests read it.
 *
 * @param stage           what the window is doing
 * @param divisor         the pass under way (or the last one) draws at 1/divisor of the window's resolution
 * @param fraction        the share of that pass's pixels drawn, 0..1
 * @param state           the state being refined (null before the first frame)
 * @param passesCompleted passes completed since the window opened, previews included
 * @param refinedFrames   refinements completed (full resolution, configured settings) since the window opened
 */
public record RefinementStatus(Stage stage, int divisor, double fraction, ViewerState state, long passesCompleted,
                               long refinedFrames) {
    /** What the window is doing. */
    public enum Stage {
        /** Nothing drawn yet. */
        STARTING,
        /** Drawing the cheap preview ({@link PreviewPolicy}) at 1/divisor of the resolution. */
        PREVIEW,
        /** Drawing the configured settings at 1/divisor of the resolution. */
        REFINING,
        /** The preview is refined; the baked table of the configured settings is still being baked. */
        WAITING_FOR_TABLE,
        /** The full-resolution picture of the configured settings is shown; nothing left to draw. */
        REFINED,
        /** Drawing this state failed (the title's notice says why); a change tries again. */
        FAILED
    }

    static final RefinementStatus STARTING = new RefinementStatus(Stage.STARTING, 0, 0, null, 0, 0);

    /** Whether the full-resolution picture of the configured settings of {@code s}'s picture is shown. */
    public boolean isRefined(ViewerState s) {
        return stage == Stage.REFINED && state != null && state.drawableSettings().equals(s.drawableSettings())
                && state.view().equals(s.view()) && state.terms() == s.terms();
    }
}
