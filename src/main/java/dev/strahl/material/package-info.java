/**
 * Scattering functions in the local shading frame.
 *
 * <p>Directions are unit vectors pointing AWAY from the surface. {@code wo}: towards the previous
 * path vertex (the camera side); {@code wi}: towards the next vertex (the light side). In the
 * local frame z = n (the shading normal), so cosθ(w) = w.z. BSDF values exclude the cosine
 * factor; the weight returned by sampling includes it. This package sees only local vectors and
 * never imports geometry.
 */
package dev.strahl.material;
