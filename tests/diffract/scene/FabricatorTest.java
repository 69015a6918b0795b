package diffract.scene;

import diffract.colour.ToneMapping;
import diffract.jrtr.scenegraph.VertexAttribute;
import diffract.lighting.ExtendedLight;
import diffract.lighting.LatLongMap;
import diffract.lighting.RadianceHdr;
import diffract.optics.settings.PixelFilter;
import diffract.optics.Variant;
import diffract.render.Stage;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The Fabricator builds the expected setup from each scene: shape, patch, settings, camera and light numbers. */
class FabricatorTest {
    @TempDir
    Path dir;

    @Test
    void theDefaultSceneIsTheDemosView() {
        Scene scene = SceneFile.load(SceneFileTest.SCENES.resolve("snake-elaphe.json"));
        SceneSetup s = Fabricator.fabricate(scene, Reporter.SILENT);
        assertEquals("snake", s.shape().name());
        assertEquals(128, s.patch().rows());
        assertEquals(128, s.patch().cols());
        assertEquals(8 * 1.144 / 128, s.patch().pixelSizeXUm(), 1e-12);
        assertEquals(Variant.LOBES, s.settings().variant());
        assertEquals(20, s.settings().taylor().highestOrder());
        assertEquals(65 / 4.0, s.settings().illumination().sigmaSpatialUm());
        assertEquals(65, s.settings().illumination().coherenceLengthUm());
        assertEquals(15, s.settings().illumination().light().angularDiameterDeg(), "a soft light beside the camera");
        assertEquals(PixelFilter.BOX, s.settings().illumination().pixelFilter());
        assertEquals(diffract.colour.MirrorNormalisation.ENERGY, s.settings().spectral().normalisation());
        assertEquals(diffract.optics.RadiometricGain.of(s.settings()), s.exposure(), 0, "radiometric");
        // eye - lookAt = (0.07, 2.22, 0.38): the orbit camera's distance and azimuth, from above
        OrbitCamera c = s.camera();
        assertEquals(Math.sqrt(0.07 * 0.07 + 2.22 * 2.22 + 0.38 * 0.38), c.distance(), 1e-9);
        assertEquals(Math.toDegrees(Math.atan2(0.07, 0.38)), c.azimuthDeg(), 1e-9);
        assertEquals(-0.12, c.targetY(), 1e-12);
        assertEquals(45, s.verticalFovDeg());
        // the corn snake's own pattern, painted on its scales, shown from the start
        assertNotNull(s.pigmentation());
        assertEquals(512, s.pigmentation().getWidth());
        assertEquals(4096, s.pigmentation().getHeight());
        assertTrue(s.pigmentationOn());
        assertEquals(DisplayMode.SURFACE, s.mode());
        assertEquals(640, scene.image().width());
        assertEquals(400, scene.image().height());
        // staged: scales, a clear sky as 8 extended lights, a ground with the key light's shadow, Reinhard
        Stage stage = s.stage();
        assertTrue(stage.staged());
        assertEquals(512, stage.scaleFrames().width());
        assertEquals(4096, stage.scaleFrames().height());
        assertEquals(8, stage.environment().lights().size());
        assertTrue(stage.shadows());
        assertEquals(ToneMapping.Operator.REINHARD, stage.toneMapping().operator());
        assertEquals("1", stage.defines().get("SCALE_FRAMES"));
        assertEquals("8", stage.defines().get("ENVIRONMENT_LIGHTS"));
    }

    @Test
    void aSceneWithoutStagingKeysIsNotStaged() throws IOException {
        Path file = dir.resolve("plain.json");
        Files.writeString(file, "{\"camera\": {\"eye\": [0, 1, 4]}, \"light\": {\"direction\": [0, 0, 1]},"
                + " \"shape\": {\"kind\": \"snake\"}, \"material\": {\"patch\": {\"procedural\": \"elaphe-like\"},"
                + " \"taylorTerms\": 4}}");
        SceneSetup s = Fabricator.fabricate(file, Reporter.SILENT);
        assertFalse(s.stage().staged());
        assertTrue(s.stage().defines().isEmpty());
    }

    @Test
    void theOtherDefaultScenes() {
        SceneSetup xenopeltis = Fabricator.fabricate(SceneFileTest.SCENES.resolve("snake-xenopeltis.json"),
                Reporter.SILENT);
        assertEquals(16 * 0.65 / 128, xenopeltis.patch().pixelSizeYUm(), 1e-12);
        assertNotNull(xenopeltis.pigmentation());
        assertEquals(8, xenopeltis.stage().environment().lights().size());
        SceneSetup blazed = Fabricator.fabricate(SceneFileTest.SCENES.resolve("blazed-grating-plane.json"),
                Reporter.SILENT);
        assertEquals("plane", blazed.shape().name());
        assertEquals(16, blazed.patch().rows());
        assertEquals(6 * 25, blazed.patch().cols());
        assertEquals(Variant.LOBES, blazed.settings().variant());
        assertEquals(3.5, blazed.camera().distance(), 1e-12);
        assertEquals(0, blazed.camera().elevationDeg(), 1e-12);
        assertEquals(30, blazed.light().thetaDeg(), 1e-9);
        assertEquals(0, blazed.light().phiDeg(), 1e-9);
        SceneSetup map = Fabricator.fabricate(SceneFileTest.SCENES.resolve("brdfmap-elaphe.json"), Reporter.SILENT);
        assertEquals(DisplayMode.BRDF_MAP, map.mode());
    }

    @Test
    void conversionsMatchTheViewersOwnDefinitions() {
        Scene.CameraSpec camera = new Scene.CameraSpec(new double[] {1, 2, -3}, new double[] {0.5, 0.25, 0},
                new double[] {0, 1, 0}, 30);
        OrbitCamera orbit = CameraManager.orbit(camera);
        double[] eye = orbit.eye();
        for (int k = 0; k < 3; k++) {
            assertEquals(camera.eye()[k], eye[k], 1e-12, "eye " + k);
        }
        double[] towards = {-0.3, 0.4, 0.8};
        LightDirection light = LightManager.light(new Scene.LightSpec(towards, "D65"));
        double norm = Math.sqrt(0.09 + 0.16 + 0.64);
        assertEquals(towards[0] / norm, light.direction().x(), 1e-12);
        assertEquals(towards[1] / norm, light.direction().y(), 1e-12);
        assertEquals(towards[2] / norm, light.direction().z(), 1e-12);
    }

    @Test
    void toleranceChoosesNAndTransformsMoveTheShape() throws IOException {
        Path file = dir.resolve("s.json");
        Files.writeString(file, "{\"camera\": {\"eye\": [0, 1, 4], \"lookAt\": [2, 0, 0], \"fieldOfViewDeg\": 30},"
                + " \"light\": {\"direction\": [0, 0, 1]}, \"image\": {\"width\": 32, \"height\": 16},"
                + " \"shape\": {\"kind\": \"sphere\", \"transform\": {\"translate\": [2, 0, 0], \"rotateDeg\": [0, 90, 0],"
                + " \"scale\": 0.5}, \"tangents\": {\"project\": [0, 1, 0]}},"
                + " \"material\": {\"patch\": {\"procedural\": \"xenopeltisLike\"}, \"tolerance\": 1e-3,"
                + " \"variant\": \"pq\"}}");
        SceneSetup s = Fabricator.fabricate(file, Reporter.SILENT);
        assertEquals(Variant.PQ, s.settings().variant());
        assertTrue(s.settings().taylor().highestOrder() > 0 && s.settings().taylor().highestOrder() < 20, "N " + s.settings().taylor().highestOrder());
        assertEquals(30, s.verticalFovDeg());
        assertEquals(2.0, s.camera().targetX());
        float[] p = s.shape().vertexData().attribute(VertexAttribute.POSITION);
        float[] t = s.shape().vertexData().attribute(VertexAttribute.TANGENT);
        float[] n = s.shape().vertexData().attribute(VertexAttribute.NORMAL);
        for (int i = 0; i < p.length; i += 3) {
            double r = Math.sqrt(Math.pow(p[i] - 2, 2) + p[i + 1] * p[i + 1] + p[i + 2] * p[i + 2]);
            assertEquals(0.5, r, 1e-5, "a unit sphere scaled by 0.5 about (2, 0, 0)");
            assertEquals(0, t[i] * n[i] + t[i + 1] * n[i + 1] + t[i + 2] * n[i + 2], 1e-5, "tangent in the surface");
        }
    }

    @Test
    void anHdrEnvironmentBecomesExtendedLightsCarryingItsPower() throws IOException {
        // a dim grey map with one bright pixel: the brightest light points at it; scale doubles every light
        int w = 64;
        int h = 32;
        float[] rgb = new float[3 * w * h];
        Arrays.fill(rgb, 0.01f);
        int column = 16;
        int row = 8;
        for (int k = 0; k < 3; k++) {
            rgb[3 * (row * w + column) + k] = 400;
        }
        LatLongMap map = new LatLongMap(w, h, rgb);
        RadianceHdr.write(dir.resolve("probe.hdr"), map, true);
        Path file = dir.resolve("probe.json");
        Files.writeString(file, "{\"camera\": {\"eye\": [0, 1, 4]}, \"light\": {\"direction\": [0, 1, 1]},"
                + " \"shape\": {\"kind\": \"sphere\"}, \"environment\": {\"file\": \"probe.hdr\", \"scale\": 2,"
                + " \"lights\": 4}, \"material\": {\"patch\": {\"procedural\": \"elaphe-like\"}, \"taylorTerms\": 4}}");
        Stage stage = Fabricator.fabricate(file, Reporter.SILENT).stage();
        List<ExtendedLight> lights = stage.environment().lights();
        assertEquals(4, lights.size());
        double[] expected = map.pixelDirection(column, row);
        double[] d = lights.get(0).direction();
        assertTrue(d[0] * expected[0] + d[1] * expected[1] + d[2] * expected[2] > Math.cos(Math.toRadians(1)));
        double total = 0;
        for (ExtendedLight l : lights) {
            total += l.rgb()[1];
        }
        assertEquals(2 * map.totalPower()[1], total, 0.01 * total, "scale 2, RGBE rounding within 1 %");
        assertEquals(null, stage.ground());
        assertEquals("4", stage.defines().get("ENVIRONMENT_LIGHTS"));
    }
}
