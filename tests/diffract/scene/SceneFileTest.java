package diffract.scene;

import diffract.colour.ToneMapping;
import diffract.geometry.SnakeMesh;
import diffract.geometry.SnakeSpecies;
import diffract.util.UserInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Every default scene parses; every kind of invalid scene gets its own one-line message with file, line and key. */
class SceneFileTest {
    static final Path SCENES = Path.of("assets", "scenes");

    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(strings = {"snake-elaphe", "snake-xenopeltis", "blazed-grating-plane", "brdfmap-elaphe",
        "viewer-snake", "viewer-sphere", "viewer-snake-scan"})
    void everyDefaultSceneParses(String name) {
        Scene scene = SceneFile.load(SCENES.resolve(name + ".json"));
        assertTrue(scene.image().width() >= 16, name);
    }

    /** A valid scene whose lines are known: line 5 is the material's patch, line 6 the variant. */
    static String valid(String materialExtra) {
        return "{\n"
                + "  \"camera\": {\"eye\": [0, 0, 3]},\n"
                + "  \"light\": {\"thetaDeg\": 30},\n"
                + "  \"shape\": {\"kind\": \"plane\"},\n"
                + "  \"material\": {\"patch\": {\"procedural\": \"blazed\"},\n"
                + "    \"variant\": \"flss\"" + materialExtra + "\n"
                + "  }\n"
                + "}\n";
    }

    private String message(String text) throws IOException {
        Path file = dir.resolve("bad.json");
        Files.writeString(file, text);
        UserInputException e = assertThrows(UserInputException.class, () -> SceneFile.load(file));
        assertTrue(!e.getMessage().contains("\n"), "one line: " + e.getMessage());
        assertTrue(e.getMessage().startsWith(file + ":"), e.getMessage());
        return e.getMessage().substring(file.toString().length() + 1);
    }

    @Test
    void theValidSceneParses() throws IOException {
        Path file = dir.resolve("ok.json");
        Files.writeString(file, valid(""));
        assertEquals(diffract.optics.Variant.FLSS, SceneFile.load(file).material().settings().variant());
    }

    /** light.profile gives the light's profile, disc by default; an unknown one is a one-line error. */
    @Test
    void theLightsProfileIsADiscUnlessTheSceneSaysGaussian() throws IOException {
        Path file = dir.resolve("ok.json");
        Files.writeString(file, valid(""));
        assertEquals(diffract.optics.settings.LightProfile.DISC,
                SceneFile.load(file).material().settings().illumination().light().profile());
        Files.writeString(file, valid("").replace("\"thetaDeg\": 30", "\"thetaDeg\": 30, \"profile\": \"gaussian\""));
        assertEquals(diffract.optics.settings.LightProfile.GAUSSIAN,
                SceneFile.load(file).material().settings().illumination().light().profile());
        String m = message(valid("").replace("\"thetaDeg\": 30", "\"thetaDeg\": 30, \"profile\": \"tophat\""));
        assertTrue(m.startsWith("3: light.profile"), m);
    }

    @Test
    void unknownKeySuggestsTheNearestKnownKey() throws IOException {
        String m = message(valid(",\n    \"exposre\": 3"));
        assertTrue(m.startsWith("7: material.exposre: unknown key (did you mean \"exposure\"?)"), m);
    }

    /**
     * {@code "exposure": "radiometric"} takes the radiometric gain of the material's coherence length and refractive
     * index and the energy normalisation; a number keeps the thesis' peak normalisation unless told otherwise.
     */
    @Test
    void radiometricExposureTakesTheGainAndTheEnergyNormalisation() throws IOException {
        Path file = dir.resolve("radiometric.json");
        Files.writeString(file, valid(",\n    \"coherenceLengthUm\": 65, \"exposure\": \"radiometric\""));
        Scene.MaterialSpec m = SceneFile.load(file).material();
        assertEquals(diffract.colour.MirrorNormalisation.ENERGY, m.settings().spectral().normalisation());
        assertEquals(diffract.optics.RadiometricGain.of(m.settings()), m.exposure(), 0);
        assertEquals(1619, m.exposure(), 1); // pi R_0 / Omega(555 nm) at 65 um on keratin, n = 1.56
        Files.writeString(file, valid(",\n    \"coherenceLengthUm\": 130, \"exposure\": \"radiometric\""));
        assertEquals(4 * m.exposure(), SceneFile.load(file).material().exposure(), 1e-9 * m.exposure(), "the gain grows as the coherence length "
                + "squared");
        Files.writeString(file, valid(",\n    \"exposure\": 3"));
        assertEquals(diffract.colour.MirrorNormalisation.PEAK,
                SceneFile.load(file).material().settings().spectral().normalisation());
        Files.writeString(file, valid(",\n    \"exposure\": 3, \"normalisation\": \"energy\""));
        assertEquals(diffract.colour.MirrorNormalisation.ENERGY,
                SceneFile.load(file).material().settings().spectral().normalisation());
    }

    /**
     * {@code "window": "local"} takes the scan's tiling of the texture coordinates, one number or [u, v]; the scan's
     * columns lie along v on a snake whose ridges run along the body; without the tiling, with another method or
     * with a wrong type the scene is refused in one line.
     */
    @Test
    void theLocalWindowTakesTheScansTiling() throws IOException {
        Path file = dir.resolve("local.json");
        Files.writeString(file, valid(",\n    \"window\": \"local\", \"skinUmPerTexcoord\": [250, 400]"));
        diffract.optics.spectra.WindowSettings w = SceneFile.load(file).material().settings().window();
        assertEquals(diffract.optics.windows.WindowPlacement.LOCAL, w.placement());
        assertEquals(new diffract.optics.patches.ScanTiling(250, 400, false), w.tiling());
        Files.writeString(file, valid(",\n    \"window\": \"local\", \"skinUmPerTexcoord\": 300")
                .replace("\"kind\": \"plane\"", "\"kind\": \"snake\""));
        assertEquals(new diffract.optics.patches.ScanTiling(300, 300, true),
                SceneFile.load(file).material().settings().window().tiling());
        String m = message(valid(",\n    \"window\": \"local\""));
        assertTrue(m.startsWith("7: material.window: \"local\" needs \"skinUmPerTexcoord\""), m);
        m = message(valid(",\n    \"window\": \"local\", \"skinUmPerTexcoord\": [1, 2, 3]"));
        assertTrue(m.startsWith("7: material.skinUmPerTexcoord: must be a number or an array of two numbers [u, v]"), m);
        m = message(valid(",\n    \"window\": \"local\", \"skinUmPerTexcoord\": 300").replace("\"flss\"",
                "\"lobes\""));
        assertTrue(m.startsWith("7: material.window: the local window is drawn by flss and nmm"), m);
    }

    @Test
    void radiometricExposureRefusesThePeakNormalisationAndOtherWords() throws IOException {
        String m = message(valid(",\n    \"exposure\": \"radiometric\", \"normalisation\": \"peak\""));
        assertTrue(m.startsWith("7: material.normalisation: must be \"energy\" with \"exposure\": \"radiometric\""),
                m);
        m = message(valid(",\n    \"exposure\": \"bright\""));
        assertTrue(m.startsWith("7: material.exposure: must be a number above 0 or \"radiometric\", got \"bright\""),
                m);
    }

    /** A key with an escaped newline (found by SceneFuzzTest) is quoted with the escape: the message stays one line. */
    @Test
    void controlCharactersInKeysAreEscapedInTheMessage() throws IOException {
        String m = message(valid(",\n    \"expo\\nsure\\t\": 3"));
        assertTrue(m.startsWith("7: material.expo\\nsure\\t: unknown key"), m);
        assertFalse(m.contains("\n"), m);
    }

    @Test
    void missingKeyNamesWhatToAdd() throws IOException {
        String m = message(valid("").replace("\"eye\": [0, 0, 3]", "\"lookAt\": [0, 0, 0]"));
        assertTrue(m.startsWith("2: camera.eye: missing; add \"eye\": [x, y, z]"), m);
    }

    @Test
    void wrongTypeNamesTheTypeGiven() throws IOException {
        String m = message(valid(",\n    \"taylorTerms\": \"twenty\""));
        assertTrue(m.startsWith("7: material.taylorTerms: must be a number in [0, 100], got a string"), m);
    }

    @Test
    void outOfRangeStatesTheRange() throws IOException {
        String m = message(valid(",\n    \"lambdaMinNm\": 200"));
        assertTrue(m.startsWith("7: material.lambdaMinNm: must be in [360, 830], got 200"), m);
        String fov = message(valid("").replace("\"eye\": [0, 0, 3]", "\"eye\": [0, 0, 3], \"fieldOfViewDeg\": 180"));
        assertTrue(fov.startsWith("2: camera.fieldOfViewDeg: must be in (0, 180), got 180"), fov);
    }

    /**
     * A method that takes another is written as its label with the parameter or as an object; both read as the same
     * method, and a method that takes none, an unknown inner method or an inner one no table holds is a one-line error.
     */
    @Test
    void aMethodThatTakesAnotherReadsInBothForms() throws IOException {
        Path file = dir.resolve("ok.json");
        diffract.optics.Variant bakedLobes = diffract.optics.Variant.BAKED.of(diffract.optics.Variant.LOBES);
        Files.writeString(file, valid("").replace("\"flss\"", "\"baked(of=lobes)\""));
        assertEquals(bakedLobes, SceneFile.load(file).material().settings().variant());
        Files.writeString(file, valid("").replace("\"flss\"", "{\"type\": \"baked\", \"of\": \"lobes\"}"));
        assertEquals(bakedLobes, SceneFile.load(file).material().settings().variant());
        assertEquals("baked(of=lobes)", bakedLobes.spec());
        assertNotEquals(diffract.optics.Variant.BAKED, bakedLobes, "plain baked chooses its table per scene");
        String pq = message(valid("").replace("\"flss\"", "{\"type\": \"baked\", \"of\": \"pq\"}"));
        assertTrue(pq.startsWith("6: material.variant.of: a baked table holds flss or lobes, not pq"), pq);
        String flss = message(valid("").replace("\"flss\"", "\"flss(of=lobes)\""));
        assertTrue(flss.startsWith("6: material.variant: flss takes no other method"), flss);
        String inner = message(valid("").replace("\"flss\"", "{\"type\": \"baked\", \"of\": \"lobbes\"}"));
        assertTrue(inner.startsWith("6: material.variant.of: unknown value \"lobbes\" (did you mean \"lobes\"?)"),
                inner);
        String extra = message(valid("").replace("\"flss\"", "{\"type\": \"baked\", \"off\": \"lobes\"}"));
        assertTrue(extra.startsWith("6: material.variant.off: unknown key (did you mean \"of\"?)"), extra);
    }

    @Test
    void unknownValueSuggestsTheNearestChoice() throws IOException {
        String m = message(valid("").replace("\"flss\"", "\"flsss\""));
        assertTrue(m.startsWith("6: material.variant: unknown value \"flsss\" (did you mean \"flss\"?)"), m);
    }

    @Test
    void missingFileIsResolvedRelativeToTheSceneFile() throws IOException {
        String m = message(valid("").replace("{\"procedural\": \"blazed\"}", "{\"file\": \"patches/none.gsf\"}"));
        assertTrue(m.startsWith("5: material.patch.file: file " + dir.resolve("patches/none.gsf") + " not found"), m);
    }

    @Test
    void aFilePatchNamesItsChannelAndLevelling() throws IOException {
        Files.writeString(dir.resolve("scan.gwy"), "read later, by the material");
        Path file = dir.resolve("scan.json");
        Files.writeString(file, valid("").replace("{\"procedural\": \"blazed\"}",
                "{\"file\": \"scan.gwy\", \"channel\": \"ZSensor\", \"level\": \"rows\"}"));
        Scene.FilePatch patch = (Scene.FilePatch) SceneFile.load(file).material().patch();
        assertEquals(new Scene.FilePatch(dir.resolve("scan.gwy"), null, null, "ZSensor",
                diffract.optics.patches.Levelling.ROWS), patch);

        Files.writeString(file, valid("").replace("{\"procedural\": \"blazed\"}",
                "{\"file\": \"scan.gwy\", \"channel\": 3}"));
        patch = (Scene.FilePatch) SceneFile.load(file).material().patch();
        assertEquals("3", patch.channel());
        assertEquals(null, patch.levelling(), "the file format's levelling by default");

        String m = message(valid("").replace("{\"procedural\": \"blazed\"}",
                "{\"file\": \"scan.gwy\", \"channel\": 1.5}"));
        assertTrue(m.startsWith("5: material.patch.channel: must be a channel's title (a string) or its index (a whole"
                + " number >= 0), got 1.5"), m);
        m = message(valid("").replace("{\"procedural\": \"blazed\"}",
                "{\"file\": \"scan.gwy\", \"level\": \"flat\"}"));
        assertTrue(m.startsWith("5: material.patch.level: unknown value \"flat\""), m);
        assertTrue(m.contains("use one of \"plane\", \"rows\", \"none\""), m);
    }

    @Test
    void malformedJsonGivesJacksonsLine() throws IOException {
        String m = message(valid("").replace("\"shape\": {", "\"shape\" {"));
        assertTrue(m.startsWith("4: (json): malformed JSON: Unexpected character"), m);
    }

    @Test
    void duplicateKeysAreRefused() throws IOException {
        String m = message(valid(",\n    \"variant\": \"pq\""));
        assertTrue(m.startsWith("7: (json): key 'variant' appears twice"), m);
    }

    @Test
    void cameraRollIsRefusedWithTheFix() throws IOException {
        String m = message(valid("").replace("\"eye\": [0, 0, 3]", "\"eye\": [0, 0, 3], \"up\": [1, 0, 0]"));
        assertTrue(m.startsWith("2: camera.up: rolls the camera by 90.0 degrees"), m);
    }

    @Test
    void aLightBelowTheHorizonIsRefused() throws IOException {
        String m = message(valid("").replace("\"thetaDeg\": 30", "\"direction\": [0, 1, -1]"));
        assertTrue(m.startsWith("3: light.direction: the light is 135.0 degrees from the +z axis"), m);
    }

    @Test
    void procedualParametersBelongToTheirKind() throws IOException {
        String m = message(valid("").replace("{\"procedural\": \"blazed\"}", "{\"procedural\": \"blazed\", \"seed\": 3}"));
        assertTrue(m.startsWith("5: material.patch.seed: unknown key"), m);
    }

    @Test
    void anEmptyFileAndANonObjectAreRefused() throws IOException {
        assertTrue(message("").startsWith("1: (json): the file is empty"));
        assertTrue(message("[1, 2]").startsWith("1: (scene): must be a JSON object"));
    }

    /** Every BRDF setting has its key, with the option's meaning: a radius or "auto", the coherence length. */
    @Test
    void theBrdfKeysMeanWhatTheOptionsMean() throws IOException {
        Path file = dir.resolve("keys.json");
        Files.writeString(file, valid(",\n    \"windowRadius\": \"auto\", \"coherenceLengthUm\": 10, \"taylorTolerance\": 1e-4,"
                + " \"expansion\": \"centred\", \"termFormat\": \"rg16f\", \"pqReplicas\": 3, \"taylorTerms\": 12")
                .replace("\"blazed\"", "\"elapheLike\""));
        Scene scene = SceneFile.load(file);
        diffract.optics.BrdfSettings s = scene.material().settings();
        assertTrue(s.window().automatic());
        assertEquals(3, s.window().pqReplicas());
        assertEquals(10, s.illumination().coherenceLengthUm(), 1e-12);
        assertEquals(1e-4, s.taylor().tolerance());
        assertEquals(12, s.taylor().highestOrder());
        assertEquals(diffract.optics.spectra.TaylorExpansion.CENTRED, s.taylor().expansion());
        assertEquals(diffract.optics.settings.TermFormat.RG16F, s.gpu().termFormat());
        assertEquals(0, s.gpu().bakedUvSamples(), "automatic unless given");
        assertEquals("elaphe-like", ((Scene.ProceduralPatch) scene.material().patch()).name(),
                "a camelCase name is the catalogue's patch");
    }

    /** Maxwell's equations' keys: the lobes method's orders, the resolution, the polarisation, the complex index. */
    @Test
    void theRigorousKeysMeanWhatTheOptionsMean() throws IOException {
        Path file = dir.resolve("rigorous.json");
        Files.writeString(file, valid(",\n    \"orders\": \"rigorous\", \"harmonics\": 30, \"layers\": 40,"
                + " \"polarisation\": \"s\", \"refractiveIndex\": 1.6, \"extinction\": 0.05")
                .replace("\"flss\"", "\"lobes\""));
        diffract.optics.BrdfSettings s = SceneFile.load(file).material().settings();
        assertEquals(diffract.optics.settings.OrderWeights.RIGOROUS, s.rigorous().orders());
        assertEquals(new diffract.optics.rigorous.Resolution(30, 40, true), s.rigorous().resolution());
        assertEquals(diffract.optics.settings.Polarisation.S, s.rigorous().polarisation());
        assertEquals(new diffract.optics.rigorous.ComplexIndex(1.6, 0.05), s.illumination().material());

        Path auto = dir.resolve("auto.json");
        Files.writeString(auto, valid(",\n    \"harmonics\": \"auto\", \"layers\": 7, \"layerExtrapolation\": false"));
        diffract.optics.BrdfSettings a = SceneFile.load(auto).material().settings();
        assertEquals(new diffract.optics.rigorous.Resolution(0, 7, false), a.rigorous().resolution());
        assertEquals(diffract.optics.settings.OrderWeights.SCALAR, a.rigorous().orders(),
                "the scalar orders by default");
        assertEquals(diffract.optics.illumination.GainFactor.KERATIN_REFRACTIVE_INDEX,
                a.illumination().refractiveIndex());
    }

    /** Each rigorous key's mistake is named at its key with the way out. */
    @Test
    void theRigorousKeysMistakesAreNamed() throws IOException {
        String odd = message(valid(",\n    \"layers\": 7"));
        assertTrue(odd.startsWith("7: material.layers: the staircase is extrapolated from L / 2 and L layers"), odd);
        String word = message(valid(",\n    \"harmonics\": \"many\""));
        assertTrue(word.startsWith("7: material.harmonics: must be a whole number in [1, 2000] or \"auto\""), word);
        String flss = message(valid(",\n    \"orders\": \"rigorous\""));
        assertTrue(flss.startsWith("7: material.orders: flss draws the scalar model's orders"), flss);
        String polar = message(valid(",\n    \"polarisation\": \"q\""));
        assertTrue(polar.contains("material.polarisation: unknown value \"q\""), polar);
        String k = message(valid(",\n    \"extinction\": -1"));
        assertTrue(k.contains("material.extinction:"), k);
    }

    /** A value the settings refuse is reported at its key, in the settings' words. */
    @Test
    void aValueTheSettingsRefuseNamesItsKey() throws IOException {
        String m = message(valid(",\n    \"taylorTolerance\": 1"));
        assertTrue(m.startsWith("7: material.taylorTolerance: the per-lookup Taylor tolerance must be in [0, 1)"), m);
        String baked = message(valid(",\n    \"bakedUvSamples\": 1"));
        assertTrue(baked.startsWith("7: material.bakedUvSamples: the baked table's samples must be 0 (automatic)"), baked);
        String both = message(valid(",\n    \"sigmaSpatialUm\": 2.5, \"coherenceLengthUm\": 10"));
        assertTrue(both.contains("material.sigmaSpatialUm: give either"), both);
    }

    /** The staging keys: values read with their units, mistakes named by key with the way out. */
    @Test
    void stagingKeysAreReadAndTheirMistakesNamed() throws IOException {
        String snake = "{\n  \"camera\": {\"eye\": [0, 1, 3]},\n  \"light\": {\"thetaDeg\": 30},\n"
                + "  \"shape\": {\"kind\": \"snake\", \"pose\": \"coiled\", \"scales\": {\"species\": \"elapheGuttata\","
                + " \"dorsalScaleRows\": 25, \"tiltDeg\": 9}},\n"
                + "  \"material\": {\"patch\": {\"procedural\": \"elaphe-like\"}, \"pigmentation\": \"xenopeltisUnicolor\"},\n"
                + "  \"environment\": {\"sky\": {\"irradianceRatio\": 0.2}, \"lights\": 4},\n"
                + "  \"ground\": {\"albedoSrgb\": [0.5, 0.4, 0.3], \"shadows\": false},\n"
                + "  \"toneMapping\": {\"operator\": \"aces\", \"exposureStops\": -1.5}\n}\n";
        Path file = dir.resolve("staged.json");
        Files.writeString(file, snake);
        Scene scene = SceneFile.load(file);
        assertEquals(SnakeMesh.Pose.COILED, scene.shape().pose());
        assertEquals(25, scene.shape().scales().lattice().dorsalRows());
        assertEquals(9, scene.shape().scales().lattice().tiltDeg());
        assertEquals(SnakeSpecies.ELAPHE_GUTTATA.scales().ventralScales(),
                scene.shape().scales().lattice().ventralScales());
        assertEquals(SnakeSpecies.XENOPELTIS_UNICOLOR, scene.material().pigmentation().species());
        assertEquals(4, scene.stage().environment().lights());
        assertEquals(0.2, scene.stage().environment().skyIrradianceRatio());
        assertEquals(false, scene.stage().ground().shadows());
        assertEquals(ToneMapping.Operator.ACES, scene.stage().toneMapping().operator());
        assertEquals(-1.5, scene.stage().toneMapping().exposureStops());

        String m = message(snake.replace("\"lights\": 4", "\"lights\": 6"));
        assertTrue(m.startsWith("6: environment.lights: must be a power of two"), m);
        m = message(snake.replace("\"species\": \"elapheGuttata\"", "\"species\": \"elapheGutata\""));
        assertTrue(m.contains("shape.scales.species: unknown value \"elapheGutata\" (did you mean \"elapheGuttata\"?)"), m);
        m = message(snake.replace("\"sky\": {\"irradianceRatio\": 0.2}, ", ""));
        assertTrue(m.contains("environment.sky: missing; add \"sky\""), m);
        m = message(snake.replace("\"operator\": \"aces\"", "\"operator\": \"filmic\""));
        assertTrue(m.contains("toneMapping.operator: unknown value \"filmic\""), m);
        m = message(snake.replace("\"tiltDeg\": 9", "\"tiltDeg\": 45"));
        assertTrue(m.contains("shape.scales.tiltDeg: must be in [0, 30], got 45"), m);
        m = message(snake.replace("\"kind\": \"snake\", \"pose\": \"coiled\"", "\"kind\": \"snake\", \"pose\": \"curled\""));
        assertTrue(m.contains("shape.pose: unknown value \"curled\""), m);
    }
}
