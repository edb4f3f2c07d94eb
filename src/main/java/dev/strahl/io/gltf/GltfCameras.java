package dev.strahl.io.gltf;

import dev.strahl.scene.Camera;
import dev.strahl.scene.SceneException;
import org.joml.Matrix4d;
import org.joml.Vector3d;

/**
 * glTF cameras: the first perspective camera placed by a node becomes the scene's camera. A glTF
 * camera looks down its node's −Z with +Y up (§3.10.1); {@code yfov} is the vertical field of
 * view in radians, as strahl's; {@code aspectRatio} is handed on to set the film's shape when no
 * size is given, and the side not given when only one is. {@code znear}/{@code zfar} mean nothing to a ray tracer. Orthographic cameras are
 * refused with a note (strahl has none), and so is a camera whose node scales it to nothing.
 */
final class GltfCameras {
    /**
     * The camera found, with the aspect ratio (width / height) it asks for.
     *
     * @param camera      the camera in world space
     * @param aspectRatio width / height, or 0 when the glTF camera does not say
     */
    record Found(Camera camera, double aspectRatio) {}

    private GltfCameras() {}

    /** The first perspective camera among the placed ones, or null. */
    static Found first(GltfDocument doc, GltfNodes nodes) throws SceneException {
        for (GltfNodes.Placed placed : nodes.cameras) {
            GltfJson cam = doc.root.array("cameras").get(placed.element());
            String type = cam.require("type").string();
            if (type.equals("orthographic")) {
                doc.noteOnce("orthographic camera " + cam.path() + " is not supported: skipped");
                continue;
            }
            if (!type.equals("perspective")) {
                throw cam.get("type").error("unknown camera type " + cam.get("type").quoted() + " (known: orthographic, perspective)");
            }
            GltfJson p = cam.require("perspective");
            GltfJson yfovNode = p.require("yfov");
            double yfov = Math.toDegrees(yfovNode.number());
            if (!(yfov > 0 && yfov < 180)) {
                throw yfovNode.error("yfov must lie in (0, pi) radians, got " + yfovNode.number());
            }
            double aspect = p.number("aspectRatio", 0);
            if (p.has("aspectRatio") && !(aspect > 0 && aspect < 1e4)) {
                throw p.get("aspectRatio").error("aspectRatio must be positive, got " + aspect);
            }
            Matrix4d m = placed.world();
            Vector3d from = m.transformPosition(new Vector3d(0, 0, 0));
            Vector3d at = m.transformPosition(new Vector3d(0, 0, -1));
            Vector3d up = m.transformDirection(new Vector3d(0, 1, 0));
            try {
                return new Found(new Camera(from, at, up, yfov), aspect);
            } catch (IllegalArgumentException e) {
                doc.noteOnce("camera of nodes[" + placed.node() + "] is unusable (" + e.getMessage() + "): skipped");
            }
        }
        return null;
    }

    /** A film size for {@code aspectRatio} (width / height) with {@code width} pixels across. */
    static int heightFor(int width, double aspectRatio) {
        return Math.max(1, (int) Math.round(width / aspectRatio));
    }
}
