/**
 * strahl, a physically based renderer: build or load a scene, render it progressively on all
 * cores, write PNG or PFM. The front door is {@link dev.strahl.scene.Scene},
 * {@link dev.strahl.scene.SceneLoader}, {@link dev.strahl.render.RenderSettings},
 * {@link dev.strahl.render.RenderJob} and {@link dev.strahl.film.ImageWriters}; docs/architecture.md
 * lists every API type.
 */
module dev.strahl {
    requires transitive java.desktop;          // BufferedImage in the film API; Swing in the viewer
    requires java.management;
    requires jdk.management;                   // the viewer's CPU load figure
    requires transitive org.joml;              // vectors in the camera, sphere and transform API
    requires com.fasterxml.jackson.core;       // the scene file parser
    requires info.picocli;
    requires com.formdev.flatlaf;
    requires jdk.unsupported;                  // sun.misc.Signal: Ctrl-C stops a render and keeps its image
    requires static jdk.incubator.vector;      // the optional SIMD box test of the BVH (accel/SimdNodes), used when present

    exports dev.strahl.scene;
    exports dev.strahl.render;
    exports dev.strahl.film;
    exports dev.strahl.material;
    exports dev.strahl.math;
    exports dev.strahl.camera;
    exports dev.strahl.geometry;
    exports dev.strahl.integrator;
    exports dev.strahl.sampling;

    // picocli reads and sets the annotated command fields reflectively
    opens dev.strahl.cli to info.picocli;
}
