/**
 * strahl, a physically based renderer: build a scene in code or load one from a file, render it
 * progressively on all cores, write the image. The API is four packages:
 * {@link dev.strahl.scene} (the scene: shapes, materials, camera), {@link dev.strahl.render}
 * (settings, render jobs, their listener and figures), {@link dev.strahl.image} (colours and
 * images) and {@link dev.strahl.io} (loading scenes, writing images). docs/architecture.md lists
 * every API type.
 *
 * <p>The command line (picocli) and the viewer's look and feel (FlatLaf) are optional
 * dependencies: a program that uses strahl as a library never needs them.
 */
module dev.strahl {
    requires transitive org.joml;              // vectors in the camera and scene-building API
    requires com.fasterxml.jackson.core;       // the scene file parser
    requires java.desktop;                     // ImageIO for PNG; Swing in the viewer
    requires java.management;
    requires java.prefs;                       // the viewer's File → Open Recent list
    requires jdk.management;                   // the viewer's CPU load figure
    requires jdk.unsupported;                  // sun.misc.Signal: Ctrl-C stops a render and keeps its image
    requires static info.picocli;              // the command line only
    requires static com.formdev.flatlaf;       // the viewer only
    requires static com.hazelcast.core;        // clusters only (dev.strahl.cluster, loaded by RenderCluster when one is joined)
    requires static jdk.incubator.vector;      // the SIMD ray kernel (accel/SimdKernel), used when present

    exports dev.strahl.scene;
    exports dev.strahl.render;
    exports dev.strahl.image;
    exports dev.strahl.io;

    // picocli reads and sets the annotated command fields reflectively
    opens dev.strahl.cli to info.picocli;
}
