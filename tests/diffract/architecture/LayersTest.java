package diffract.architecture;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.lang.ArchRule;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

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
 */
class LayersTest {
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
}
