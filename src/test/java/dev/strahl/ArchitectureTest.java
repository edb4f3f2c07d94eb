package dev.strahl;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;

import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.core.importer.Location;
import com.tngtech.archunit.junit.AnalyzeClasses;
import com.tngtech.archunit.junit.ArchTest;
import com.tngtech.archunit.lang.ArchRule;

/**
 * The package layering of STYLE.md, checked on the compiled main classes, so that a wrong import
 * fails the build instead of a review. An arrow means "may be used by":
 * <pre>
 * math ← sampling ← { geometry, material, film } ← { accel, light, camera } ← scene ← integrator ← render ← viewer ← cli
 * </pre>
 * A layer may use every layer below it, never one above it or a sibling on its own tier; on top of
 * that, material never sees geometry (it works in the local frame), the integrator never sees the
 * film, the render loop or the user interfaces, and Swing and picocli stay in the user interfaces.
 * The viewer layer may still be empty: it is optional, every other layer must exist.
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

    @ArchTest
    static final ArchRule layers = layeredArchitecture().consideringOnlyDependenciesInLayers()
            .layer("math").definedBy("dev.strahl.math..")
            .layer("sampling").definedBy("dev.strahl.sampling..")
            .layer("geometry").definedBy("dev.strahl.geometry..")
            .layer("material").definedBy("dev.strahl.material..")
            .layer("film").definedBy("dev.strahl.film..")
            .layer("accel").definedBy("dev.strahl.accel..")
            .layer("light").definedBy("dev.strahl.light..")
            .layer("camera").definedBy("dev.strahl.camera..")
            .layer("scene").definedBy("dev.strahl.scene..")
            .layer("integrator").definedBy("dev.strahl.integrator..")
            .layer("render").definedBy("dev.strahl.render..")
            .optionalLayer("viewer").definedBy("dev.strahl.viewer..")
            .layer("cli").definedBy("dev.strahl.cli..")

            .whereLayer("cli").mayNotBeAccessedByAnyLayer()
            .whereLayer("viewer").mayOnlyBeAccessedByLayers("cli")
            .whereLayer("render").mayOnlyBeAccessedByLayers("viewer", "cli")
            .whereLayer("integrator").mayOnlyBeAccessedByLayers("render", "viewer", "cli")
            .whereLayer("scene").mayOnlyBeAccessedByLayers("integrator", "render", "viewer", "cli")
            .whereLayer("accel").mayOnlyBeAccessedByLayers("scene", "integrator", "render", "viewer", "cli")
            .whereLayer("light").mayOnlyBeAccessedByLayers("scene", "integrator", "render", "viewer", "cli")
            .whereLayer("camera").mayOnlyBeAccessedByLayers("scene", "integrator", "render", "viewer", "cli")
            .whereLayer("geometry").mayOnlyBeAccessedByLayers("accel", "light", "camera", "scene", "integrator", "render", "viewer", "cli")
            .whereLayer("material").mayOnlyBeAccessedByLayers("accel", "light", "camera", "scene", "integrator", "render", "viewer", "cli")
            // The integrator is the one layer above film that must not use it.
            .whereLayer("film").mayOnlyBeAccessedByLayers("accel", "light", "camera", "scene", "render", "viewer", "cli")
            .whereLayer("sampling").mayOnlyBeAccessedByLayers("geometry", "material", "film", "accel", "light", "camera", "scene",
                    "integrator", "render", "viewer", "cli")
            .whereLayer("math").mayOnlyBeAccessedByLayers("sampling", "geometry", "material", "film", "accel", "light", "camera", "scene",
                    "integrator", "render", "viewer", "cli");

    @ArchTest
    static final ArchRule materialNeverSeesGeometry = noClasses().that().resideInAPackage("dev.strahl.material..")
            .should().dependOnClassesThat().resideInAPackage("dev.strahl.geometry..")
            .because("BSDFs work in the local shading frame and need no geometry (STYLE.md)");

    @ArchTest
    static final ArchRule integratorKnowsNoFilmThreadsOrFiles = noClasses().that().resideInAPackage("dev.strahl.integrator..")
            .should().dependOnClassesThat().resideInAnyPackage("dev.strahl.film..", "dev.strahl.render..", "dev.strahl.cli..",
                    "dev.strahl.viewer..")
            .because("an integrator answers one question, the radiance along a ray (STYLE.md habit 9)");

    @ArchTest
    static final ArchRule renderUsesNoUserInterface = noClasses().that().resideInAPackage("dev.strahl.render..")
            .should().dependOnClassesThat().resideInAnyPackage("javax.swing..", "picocli..")
            .because("the render loop reports progress through listeners, never to a UI toolkit (STYLE.md habit 9)");

    @ArchTest
    static final ArchRule swingOnlyInTheUserInterfaces = noClasses().that()
            .resideOutsideOfPackages("dev.strahl.viewer..", "dev.strahl.cli..")
            .should().dependOnClassesThat().resideInAPackage("javax.swing..")
            .because("only the viewer (and the CLI that starts it) may use Swing");

    @ArchTest
    static final ArchRule picocliOnlyInTheCli = noClasses().that().resideOutsideOfPackage("dev.strahl.cli..")
            .should().dependOnClassesThat().resideInAPackage("picocli..")
            .because("command-line parsing belongs to the cli package");
}
