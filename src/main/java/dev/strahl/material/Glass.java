package dev.strahl.material;

import dev.strahl.color.MutableRgb;
import org.joml.Vector2dc;
import org.joml.Vector3dc;

/**
 * Clear glass, smooth ({@link Dielectric}) or rough ({@link RoughDielectric}): an interface with an
 * inside, so one-sided (which side a ray comes from decides η), and nothing absorbed, so its albedo
 * is 1 whether the light is reflected or transmitted.
 */
public sealed interface Glass extends Bsdf permits Dielectric, RoughDielectric {

    @Override
    default boolean isTwoSided() {
        return false;
    }

    /** 1: clear glass scatters (reflects or transmits) all light, untinted. */
    @Override
    default void albedo(Vector2dc uv, Vector3dc wo, MutableRgb dest) {
        dest.set(1, 1, 1);
    }
}
