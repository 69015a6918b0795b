package diffract.architecture;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.lang.ArchRule;
import com.tngtech.archunit.library.Architectures.LayeredArchitecture;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

/**
 * The layers of the code, from the bottom: {@code util} (reporting, errors, files), {@code colour}, {@code geometry}
 * (CPU meshes and the scale lattice), {@code lighting} (environment light on the CPU) and {@code optics} (the BRDF and
 * its settings); {@code precompute} (the Taylor terms); the GL engine {@code jrtr}, which knows nothing of
 * diffraction, and the GPU materials {@code render}; the {@code pipeline} that every command takes from a height field
 * to a picture; {@code scene} (what a scene file or a command line describes, and the Fabricator); {@code viewer} and
 * {@code bench}; and the command line {@code app}. A layer uses only the layers below it; the domain below the engine
 * uses neither OpenGL nor the command line.
 *
 * <p>Inside the largest layers the classes live in rooms, one package per concept, and the rooms of a layer form an
 * order too: a room uses only the rooms on the tiers below it, never a sibling on its own tier and never one above.
 * Each room stays small enough to read as one thing ({@link #noRoomHoldsMoreThanThirtyFiles}).
 */
class LayersTest {
    /** The most Java files one package of the rooms' layers holds before it asks to be split. */
    private static final int ROOM_FILES_MAX = 30;
    static JavaClasses classes;

    @BeforeAll
    static void importMainClasses() {
        classes = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("diffract");
        // an empty import would let every rule pass
        assertTrue(classes.size() > 150, "imported " + classes.size() + " classes");
    }

    @Test
    void layersOnlyUseTheLayersBelowThem() {
        ArchRule layers = layeredArchitecture().consideringOnlyDependenciesInLayers()
                .layer("App").definedBy("diffract.app..")
                .layer("Viewer").definedBy("diffract.viewer..")
                .layer("Bench").definedBy("diffract.bench..")
                .layer("Scene").definedBy("diffract.scene..")
                .layer("Pipeline").definedBy("diffract.pipeline..")
                .layer("Materials").definedBy("diffract.render..")
                .layer("Engine").definedBy("diffract.jrtr..")
                .layer("Precompute").definedBy("diffract.precompute..")
                .layer("Optics").definedBy("diffract.optics..")
                .layer("Lighting").definedBy("diffract.lighting..")
                .layer("Geometry").definedBy("diffract.geometry..")
                .layer("Colour").definedBy("diffract.colour..")
                .layer("Util").definedBy("diffract.util..")
                .whereLayer("App").mayNotBeAccessedByAnyLayer()
                .whereLayer("Viewer").mayOnlyBeAccessedByLayers("App")
                .whereLayer("Bench").mayOnlyBeAccessedByLayers("App")
                .whereLayer("Scene").mayOnlyBeAccessedByLayers("Viewer", "App")
                .whereLayer("Pipeline").mayOnlyBeAccessedByLayers("Scene", "Viewer", "Bench", "App")
                .whereLayer("Materials").mayOnlyBeAccessedByLayers("Pipeline", "Scene", "Viewer", "Bench", "App")
                .whereLayer("Engine").mayOnlyBeAccessedByLayers("Materials", "Pipeline", "Scene", "Viewer", "Bench", "App")
                .whereLayer("Precompute").mayOnlyBeAccessedByLayers("Materials", "Pipeline", "Scene", "Viewer", "Bench",
                        "App")
                .whereLayer("Optics").mayOnlyBeAccessedByLayers("Precompute", "Materials", "Pipeline", "Scene", "Viewer",
                        "Bench", "App")
                .whereLayer("Lighting").mayOnlyBeAccessedByLayers("Materials", "Pipeline", "Scene", "Viewer", "Bench",
                        "App")
                .whereLayer("Geometry").mayOnlyBeAccessedByLayers("Scene", "Viewer", "Bench", "App")
                .whereLayer("Colour").mayOnlyBeAccessedByLayers("Optics", "Precompute", "Materials", "Pipeline", "Scene",
                        "Viewer", "Bench", "App");
        layers.check(classes);
    }

    @Test
    void noPackageCycles() {
        slices().matching("diffract.(*)..").should().beFreeOfCycles().check(classes);
    }

    @Test
    void theDomainUsesNeitherOpenGlNorTheCommandLine() {
        noClasses().that().resideInAnyPackage("diffract.util..", "diffract.colour..", "diffract.geometry..",
                        "diffract.lighting..", "diffract.optics..", "diffract.precompute..")
                .should().dependOnClassesThat().resideInAnyPackage("com.jogamp..", "picocli..")
                .check(classes);
    }

    @Test
    void onlyTheCommandLineUsesPicocli() {
        noClasses().that().resideOutsideOfPackage("diffract.app..")
                .should().dependOnClassesThat().resideInAPackage("picocli..").check(classes);
    }

    @Test
    void theEngineKnowsNothingOfDiffraction() {
        noClasses().that().resideInAPackage("diffract.jrtr..")
                .should().dependOnClassesThat().resideInAnyPackage("diffract.colour..", "diffract.optics..",
                        "diffract.geometry..", "diffract.lighting..", "diffract.precompute..", "diffract.render..")
                .check(classes);
    }

    /**
     * The optics, from the bottom. {@code numerics} (error function, quadrature rules, 2x2 covariances, the shifted
     * DFT) and {@code settings} (the named quantities, the exception that names one, and the small choices a setting
     * picks from: gain model, light profile, pixel filter, polarisation, order weights, wavelengths) stand on nothing.
     * {@code patches} (height fields and the directions of their tangent frame, the shipped and synthetic patches,
     * levelling, scan tiling) and {@code windows} (the coherence window and where it sits) use only those. On them
     * stand {@code spectra} (a patch's spectrum, exact or as a Taylor series, and the Taylor and window settings that
     * shape it), {@code io} (scans read into height fields) and {@code rigorous} (Maxwell's equations on a periodic
     * cell, and its settings). {@code illumination} (light sources, their footprints in frequency
     * space, the gain, and the illumination settings, whose material is a complex index of refraction) needs the
     * coherence window and the rigorous solver's index; {@code lobes} (the Gaussian lobes and their weights) builds on
     * the spectra and the footprints. The package {@code diffract.optics} itself holds the BRDF and the methods with
     * their registry: {@code Variant} constructs every method and every method takes {@code BrdfSettings} and returns
     * into {@code DiffractionBrdf}, so they are one room and sit above everything they draw on. On top, what is asked
     * of a BRDF once built: {@code maps} (exposure and differences of BRDF maps), {@code validity} (the scalar model
     * against Maxwell's equations) and {@code baked} (tables for renderers outside diffract).
     */
    @Test
    void theOpticsRoomsFormAnOrder() {
        ordered("diffract.optics",
                List.of("numerics", "settings"),
                List.of("patches", "windows"),
                List.of("spectra", "io", "rigorous"),
                List.of("illumination"),
                List.of("lobes"),
                List.of(""),
                List.of("maps", "validity", "baked")).check(classes);
    }

    /**
     * The engine, from the bottom: {@code gl} (error checks, GPU resources, timers) and {@code shaders} (GLSL
     * sources, their preprocessor and the compiled stages) stand on nothing; {@code textures} (textures, float
     * framebuffers, mipmaps, depth bounds) on the GL basics; {@code contexts} (EGL, hidden JOGL drawables, onscreen
     * windows, which GL a machine offers) draws into float framebuffers; {@code scenegraph} (nodes, shapes, materials,
     * shader programs, cameras and what a frame draws) binds textures and shaders and asks a context what it offers;
     * the package {@code diffract.jrtr} itself holds the renderer, the offscreen target and the shadow map, which tie
     * a scene graph to a context.
     */
    @Test
    void theEngineRoomsFormAnOrder() {
        ordered("diffract.jrtr",
                List.of("gl", "shaders"),
                List.of("textures"),
                List.of("contexts"),
                List.of("scenegraph"),
                List.of("")).check(classes);
    }

    /**
     * The command line: {@code options} (the option mixins shared by commands, their names and converters) and
     * {@code jobs} (pieces, their manifests and folders, tiling, Slurm scripts) know no command; the package
     * {@code diffract.app} itself holds the commands, which use both, and the workers and submitters that run the
     * program itself again.
     */
    @Test
    void theCommandLineRoomsFormAnOrder() {
        ordered("diffract.app",
                List.of("options", "jobs"),
                List.of("")).check(classes);
    }

    @Test
    void noRoomCycles() {
        for (String layer : List.of("optics", "jrtr", "app", "render")) {
            slices().matching("diffract." + layer + ".(**)").should().beFreeOfCycles().allowEmptyShould(true)
                    .check(classes);
        }
    }

    /** Counts the Java files of each package under the rooms' layers in the sources, so a growing room fails here. */
    @Test
    void noRoomHoldsMoreThanThirtyFiles() throws IOException {
        List<String> crowded = new ArrayList<>();
        int packages = 0;
        for (String layer : List.of("optics", "render", "jrtr", "app")) {
            try (Stream<Path> dirs = Files.walk(Path.of("src", "diffract", layer))) {
                for (Path dir : dirs.filter(Files::isDirectory).toList()) {
                    long files;
                    try (Stream<Path> in = Files.list(dir)) {
                        files = in.filter(f -> f.toString().endsWith(".java")).count();
                    }
                    packages++;
                    if (files > ROOM_FILES_MAX) {
                        crowded.add(dir + ": " + files + " files");
                    }
                }
            }
        }
        assertTrue(packages >= 20, "counted " + packages + " packages");
        assertTrue(crowded.isEmpty(), "packages over " + ROOM_FILES_MAX + " files:\n" + String.join("\n", crowded));
    }

    /**
     * The rooms of {@code base}, tier by tier from the bottom ("" for {@code base} itself): a room is used only by
     * the rooms on higher tiers.
     */
    @SafeVarargs
    private static LayeredArchitecture ordered(String base, List<String>... tiers) {
        LayeredArchitecture rule = layeredArchitecture().consideringOnlyDependenciesInLayers();
        for (List<String> tier : tiers) {
            for (String room : tier) {
                rule = rule.layer(name(base, room)).definedBy(room.isEmpty() ? base : base + "." + room + "..");
            }
        }
        for (int t = 0; t < tiers.length; t++) {
            List<String> above = new ArrayList<>();
            for (int u = t + 1; u < tiers.length; u++) {
                for (String room : tiers[u]) {
                    above.add(name(base, room));
                }
            }
            for (String room : tiers[t]) {
                rule = above.isEmpty() ? rule.whereLayer(name(base, room)).mayNotBeAccessedByAnyLayer()
                        : rule.whereLayer(name(base, room)).mayOnlyBeAccessedByLayers(above.toArray(String[]::new));
            }
        }
        return rule;
    }

    private static String name(String base, String room) {
        return room.isEmpty() ? base : base + "." + room;
    }
}
