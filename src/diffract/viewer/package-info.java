/**
 * The interactive viewer, model-view-controller:
 *
 * <ul>
 *   <li>Model: {@link diffract.viewer.ViewerModel} holds what does not change while the window is open (the patch,
 *       the shape, the pigmentation image, where more Taylor terms come from) and an immutable
 *       {@link diffract.viewer.ViewerState} snapshot of everything the user changes (BRDF settings, orbit camera,
 *       light, exposure, display mode, the terms at hand, precompute progress). Any thread may read or replace the
 *       snapshot; the render thread reads one snapshot per frame, so a frame never mixes two states.</li>
 *   <li>View: {@link diffract.viewer.ViewerWindow} (a jrtr {@link diffract.jrtr.contexts.OnscreenWindow} and a render
 *       loop) drawing by progressive refinement ({@link diffract.viewer.RefiningRenderer}: a preview, then the
 *       configured settings at rising resolutions, in tiles short enough for the loop to take input between them)
 *       with a {@link diffract.viewer.ViewerRenderer}; the same renderer draws whole frames offscreen for
 *       {@code diffract render}.</li>
 *   <li>Controller: {@link diffract.viewer.ViewerController} queues mouse and key actions for the render loop and
 *       starts background work ({@link diffract.viewer.TermPrecomputer}, {@link diffract.viewer.TableBaker},
 *       screenshots) so the window never waits.</li>
 * </ul>
 *
 * <p>A scene's {@link diffract.scene.SceneSetup} (the patch's pipeline, shape, pigmentation, settings, camera,
 * light) becomes a model through {@link diffract.viewer.ViewerModel#load}. Above the scene, the pipeline, the GPU
 * materials and the engine, which it uses; only the command line uses it.
 */
package diffract.viewer;
