/**
 * The interactive viewer, model-view-controller:
 *
 * <ul>
 *   <li>Model: {@link diffract.viewer.ViewerModel} holds what does not change while the window is open (the patch,
 *       the shape, the pigmentation image, where more Taylor terms come from) and an immutable
 *       {@link diffract.viewer.ViewerState} snapshot of everything the user changes (BRDF settings, orbit camera,
 *       light, exposure, display mode, the terms at hand, precompute progress). Any thread may read or replace the
 *       snapshot; the render thread reads one snapshot per frame, so a frame never mixes two states.</li>
 *   <li>View: {@link diffract.viewer.ViewerWindow} (a jrtr {@link diffract.jrtr.OnscreenWindow}) drawing with a
 *       {@link diffract.viewer.ViewerRenderer}; the same renderer draws offscreen for {@code diffract render}.</li>
 *   <li>Controller: {@link diffract.viewer.ViewerController} maps mouse and keys to model changes and starts
 *       background work ({@link diffract.viewer.TermPrecomputer}, screenshots) so the window never waits.</li>
 * </ul>
 *
 * <p>A scene file fills a {@link diffract.viewer.ViewerSetup} (patch, shape, pigmentation, settings, camera, light)
 * and {@link diffract.viewer.ViewerModel#ViewerModel(ViewerSetup, TermSource)} turns it into a model.
 * The application layer: it may use the optics, the render wiring and the engine; none of them know it.
 */
package diffract.viewer;
