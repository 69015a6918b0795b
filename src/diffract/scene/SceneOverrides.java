package diffract.scene;

/**
 * What a command line says beside a scene file, applied to the scene itself, so that one scene model describes what
 * is drawn and {@code --dump-scene} can write it: the orbit camera's angles and distance, the key light's angles,
 * the exposure, the diffuse weight, the pigment switched off, the BRDF-map mode. A null leaves the scene's value.
 *
 * @param azimuthDeg     the camera's azimuth about the scene's look-at point
 * @param elevationDeg   its elevation
 * @param distance       its distance from the look-at point
 * @param thetaDeg       the key light's polar angle
 * @param phiDeg         its azimuth
 * @param exposure       the structural colour's gain
 * @param diffuseWeight  w_d
 * @param pigmentOff     true: no pigment
 * @param brdfMap        true: the BRDF map instead of the surface
 */
public record SceneOverrides(Double azimuthDeg, Double elevationDeg, Double distance, Double thetaDeg, Double phiDeg,
                             Double exposure, Double diffuseWeight, boolean pigmentOff, boolean brdfMap) {
    /** The scene with these values in place of its own. */
    public Scene applyTo(Scene s) {
        Scene.CameraSpec camera = s.camera();
        if (azimuthDeg != null || elevationDeg != null || distance != null) {
            OrbitCamera c = CameraManager.orbit(camera);
            OrbitCamera moved = new OrbitCamera(azimuthDeg != null ? azimuthDeg : c.azimuthDeg(),
                    elevationDeg != null ? elevationDeg : c.elevationDeg(), distance != null ? distance : c.distance(),
                    c.targetX(), c.targetY(), c.targetZ());
            camera = new Scene.CameraSpec(moved.eye(), camera.lookAt(), camera.up(), camera.fieldOfViewDeg());
        }
        Scene.LightSpec light = s.light();
        if (thetaDeg != null || phiDeg != null) {
            LightDirection l = LightManager.light(light);
            var d = new LightDirection(thetaDeg != null ? thetaDeg : l.thetaDeg(), phiDeg != null ? phiDeg : l.phiDeg())
                    .direction();
            light = new Scene.LightSpec(new double[] {d.x(), d.y(), d.z()}, light.spectrum());
        }
        Scene.MaterialSpec m = s.material();
        Scene.MaterialSpec material = new Scene.MaterialSpec(m.patch(), m.settings(), m.orderTolerance(),
                m.pigmentation(), m.pigmentationOn() && !pigmentOff,
                diffuseWeight != null ? diffuseWeight : m.diffuseWeight(), exposure != null ? exposure : m.exposure());
        return new Scene(s.source(), s.image(), camera, light, s.shape(), material,
                brdfMap ? DisplayMode.BRDF_MAP : s.mode(), s.stage());
    }
}
