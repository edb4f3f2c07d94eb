package dev.strahl;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.core.importer.Location;
import com.tngtech.archunit.junit.AnalyzeClasses;
import com.tngtech.archunit.junit.ArchTest;
import com.tngtech.archunit.lang.ArchRule;

/**
 * The package map of docs/architecture.md, checked on the compiled main classes, so that a wrong
 * import fails the build instead of a review. Bottom to top (a layer may use the layers below it):
 * <pre>
 * image ← color ← math ← sampling ← texture ← { geometry, material } ← { accel, light, camera }
 *   ← files ← codec ← codec.exr ← io.text ← denoise ← denoise.net ← world ← integrator ← photon ← film ← scene ← units ← render
 *   ← { io.obj, io.ply, io.gltf } ← io.mesh ← io.json ← io ← cluster ← bench ← viewer ← cli
 * </pre>
 * On top of that: no cycle between any two packages; the scene model knows no file format;
 * material never sees geometry (it works in the local frame); the integrators never see the film,
 * the render loop or the user interfaces; Swing, FlatLaf and picocli stay in the user interfaces.
 *
 * <p>Only main classes are checked (tests may reach across layers, e.g. an integrator test renders
 * a film). ArchUnit's {@code DoNotIncludeTests} recognises test classes by the path
 * {@code target/test-classes}; builds with another directory ({@code -Dstrahl.buildDirectory=...})
 * need {@link NoTestClassesDirectory} as well.
 */
@AnalyzeClasses(packages = "dev.strahl",
        importOptions = {ImportOption.DoNotIncludeTests.class, ArchitectureTest.NoTestClassesDirectory.class})
class ArchitectureTest {

    /** Leaves out every class under a {@code test-classes} directory, wherever the build directory is. */
    static final class NoTestClassesDirectory implements ImportOption {
        @Override
        public boolean includes(Location location) {
            return !location.contains("/test-classes/");
        }
    }

    /** The layers bottom to top; each may use only those before it. */
    private static final String[] LAYERS = {"image", "color", "math", "sampling", "texture", "geometry", "material", "accel", "light", "camera",
        "files", "codec", "codec.exr", "io.text", "denoise", "denoise.net", "medium", "world", "integrator", "photon", "film", "scene", "units", "render", "io.obj", "io.ply", "io.gltf", "io.mesh", "io.json", "io",
        "cluster", "bench", "viewer", "cli"};

    @ArchTest
    static final ArchRule layers = layers();

    private static ArchRule layers() {
        var rule = layeredArchitecture().consideringOnlyDependenciesInLayers();
        for (String layer : LAYERS) {
            rule = rule.layer(layer).definedBy("dev.strahl." + layer);
        }
        for (int i = 0; i < LAYERS.length - 1; i++) {
            String[] above = java.util.Arrays.copyOfRange(LAYERS, i + 1, LAYERS.length);
            rule = rule.whereLayer(LAYERS[i]).mayOnlyBeAccessedByLayers(above);
        }
        return rule.whereLayer("cli").mayNotBeAccessedByAnyLayer();
    }

    @ArchTest
    static final ArchRule noCycles = slices().matching("dev.strahl.(**)").should().beFreeOfCycles();

    @ArchTest
    static final ArchRule theSceneModelKnowsNoFileFormat = noClasses().that().resideInAPackage("dev.strahl.scene")
            .should().dependOnClassesThat().resideInAnyPackage("dev.strahl.io", "dev.strahl.io.text..", "dev.strahl.io.obj..", "dev.strahl.io.ply..", "dev.strahl.io.gltf..", "dev.strahl.io.mesh..",
                    "dev.strahl.io.json..", "dev.strahl.codec.exr..")
            .because("file formats build scenes through the scene API, never the other way round (texture images, read by codec, are"
                    + " the one file content a material holds)");

    @ArchTest
    static final ArchRule geometryNeedsNoMaterialOrFilm = noClasses().that().resideInAPackage("dev.strahl.geometry")
            .should().dependOnClassesThat().resideInAnyPackage("dev.strahl.material", "dev.strahl.film")
            .because("geometry and material are siblings on one tier; the film is the render loop's, far above");

    @ArchTest
    static final ArchRule filmNeedsNoGeometryOrMaterial = noClasses().that().resideInAPackage("dev.strahl.film")
            .should().dependOnClassesThat().resideInAnyPackage("dev.strahl.geometry", "dev.strahl.material")
            .because("the film accumulates samples; what they hit and what scattered them is the integrator's");

    @ArchTest
    static final ArchRule materialNeverSeesGeometry = noClasses().that().resideInAPackage("dev.strahl.material..")
            .should().dependOnClassesThat().resideInAPackage("dev.strahl.geometry..")
            .because("BSDFs work in the local shading frame and need no geometry (STYLE.md)");

    @ArchTest
    static final ArchRule integratorKnowsNoFilmThreadsOrFiles = noClasses().that()
            .resideInAnyPackage("dev.strahl.integrator..", "dev.strahl.photon..")
            .should().dependOnClassesThat().resideInAnyPackage("dev.strahl.film..", "dev.strahl.render..", "dev.strahl.io..",
                    "dev.strahl.cli..", "dev.strahl.viewer..")
            .because("an integrator answers one question, the radiance along a ray (STYLE.md habit 9)");

    @ArchTest
    static final ArchRule renderUsesNoUserInterface = noClasses().that().resideInAPackage("dev.strahl.render..")
            .should().dependOnClassesThat().resideInAnyPackage("javax.swing..", "picocli..")
            .because("the render loop reports progress through listeners, never to a UI toolkit (STYLE.md habit 9)");

    @ArchTest
    static final ArchRule swingOnlyInTheUserInterfaces = noClasses().that()
            .resideOutsideOfPackages("dev.strahl.viewer..", "dev.strahl.cli..")
            .should().dependOnClassesThat().resideInAnyPackage("javax.swing..", "com.formdev..")
            .because("only the viewer (and the CLI that starts it) may use Swing and its look and feel");

    @ArchTest
    static final ArchRule picocliOnlyInTheCli = noClasses().that().resideOutsideOfPackage("dev.strahl.cli..")
            .should().dependOnClassesThat().resideInAPackage("picocli..")
            .because("command-line parsing belongs to the cli package, an optional dependency");

    @ArchTest
    static final ArchRule hazelcastOnlyInTheCluster = noClasses().that().resideOutsideOfPackage("dev.strahl.cluster")
            .should().dependOnClassesThat().resideInAPackage("com.hazelcast..")
            .because("Hazelcast is an optional dependency, loaded only when a cluster is joined (RenderCluster loads dev.strahl.cluster by name)");
}
