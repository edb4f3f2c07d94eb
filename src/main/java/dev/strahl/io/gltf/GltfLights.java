package dev.strahl.io.gltf;

import dev.strahl.image.Rgb;
import dev.strahl.scene.SceneException;
import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3d;

/**
 * KHR_lights_punctual: point, spot and directional lights placed by nodes, at the node's origin
 * and shining down its −Z. {@code color × intensity} is taken as the radiometric quantity strahl's
 * lights use (radiant intensity in W/sr for point and spot lights, irradiance for directional
 * ones), on the same scale as emissive materials' {@code emissiveFactor × emissiveStrength}
 * radiance: both of glTF's photometric units (candela, lux, nits) are read without the 683 lm/W
 * factor. {@code range} is ignored (strahl's lights fall off with the inverse square only).
 */
final class GltfLights {
    enum Kind { POINT, SPOT, DIRECTIONAL }

    /**
     * A light in world space.
     *
     * @param kind      point, spot or directional
     * @param position  where it is (point, spot)
     * @param direction the unit direction the light travels (spot, directional)
     * @param power     colour × intensity
     * @param inner     the spot's inner cone angle, radians
     * @param outer     the spot's outer cone angle, radians
     */
    record Light(Kind kind, Vector3d position, Vector3d direction, Rgb power, double inner, double outer) {}

    private GltfLights() {}

    /** The document's light definitions ({@code extensions.KHR_lights_punctual.lights}). */
    static List<GltfJson> definitions(GltfDocument doc) throws SceneException {
        GltfJson ext = GltfTextures.extension(doc.root, "KHR_lights_punctual");
        return ext == null ? List.of() : ext.array("lights");
    }

    /** The lights the nodes place, in world space. */
    static List<Light> placed(GltfDocument doc, GltfNodes nodes) throws SceneException {
        List<Light> out = new ArrayList<>();
        List<GltfJson> defs = definitions(doc);
        for (GltfNodes.Placed p : nodes.lights) {
            GltfJson def = defs.get(p.element());
            double[] colour = def.numbers("color", 3, new double[] {1, 1, 1});
            double intensity = def.number("intensity", 1);
            if (!(colour[0] >= 0 && colour[1] >= 0 && colour[2] >= 0) || !(intensity >= 0) || !Double.isFinite(intensity)) {
                throw def.error("color and intensity must not be negative");
            }
            if (def.has("range")) {
                doc.noteOnce("KHR_lights_punctual range is ignored (lights fall off with the inverse square)");
            }
            Rgb power = new Rgb(colour[0] * intensity, colour[1] * intensity, colour[2] * intensity);
            Vector3d position = p.world().transformPosition(new Vector3d());
            Vector3d direction = p.world().transformDirection(new Vector3d(0, 0, -1));
            String type = def.require("type").string();
            Kind kind;
            double inner = 0;
            double outer = Math.PI / 4;
            switch (type) {
                case "point":
                    kind = Kind.POINT;
                    break;
                case "directional":
                    kind = Kind.DIRECTIONAL;
                    break;
                case "spot": {
                    kind = Kind.SPOT;
                    GltfJson spot = def.get("spot");
                    if (spot != null) {
                        inner = spot.number("innerConeAngle", 0);
                        outer = spot.number("outerConeAngle", Math.PI / 4);
                    }
                    if (!(inner >= 0 && inner < outer && outer <= Math.PI / 2)) {
                        throw (spot != null ? spot : def).error("cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= pi/2, got "
                                + inner + " and " + outer);
                    }
                    if (Math.cos(outer) == 1) {          // narrower than a double's cosine tells apart from a ray
                        throw spot.error("outerConeAngle " + outer + " is too narrow (its cosine is 1: the narrowest cone is about 1.5e-8)");
                    }
                    break;
                }
                default:
                    throw def.get("type").error("unknown light type " + def.get("type").quoted() + " (known: directional, point, spot)");
            }
            if (!position.isFinite() || !direction.isFinite() || !Double.isFinite(power.r() + power.g() + power.b())) {
                throw def.error("the light of nodes[" + p.node() + "] is not finite (its node's transform or color x intensity overflows)");
            }
            if (kind != Kind.POINT && !(direction.lengthSquared() > 1e-24)) {
                throw def.error("the node of this light (nodes[" + p.node() + "]) scales its direction to nothing");
            }
            out.add(new Light(kind, position, kind == Kind.POINT ? new Vector3d(0, 0, -1) : direction.normalize(), power, inner, outer));
        }
        return out;
    }
}
