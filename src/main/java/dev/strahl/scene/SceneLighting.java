package dev.strahl.scene;

import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.light.Environment;
import dev.strahl.light.PunctualLight;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.joml.Vector3dc;

/**
 * The lights and the environment of a {@link Scene.Builder} (its package-private base, as
 * {@link PrincipledParameters} is {@link Material.PrincipledBuilder}'s): what lights a scene besides
 * its emissive materials, one method each, returning the builder.
 */
abstract class SceneLighting {
    final List<PunctualLight> punctual = new ArrayList<>();
    /** The environment set, or null for the default (black, or the studio sky for a scene without lights). */
    Environment environment;

    private Scene.Builder self() {
        return (Scene.Builder) this;
    }

    /**
     * Radiance arriving from every direction where rays leave the scene. Without an
     * environment, a scene with lights has a black one and a scene without lights strahl's
     * studio sky (a procedural blue sky with a soft sun, built in code).
     *
     * @param radiance the constant environment radiance
     * @return this builder
     */
    public Scene.Builder environment(Rgb radiance) {
        this.environment = Environment.constant(Objects.requireNonNull(radiance));
        return self();
    }

    /**
     * A latitude–longitude environment map, oriented as Mitsuba 3's {@code envmap}: +Y is up
     * and the image's top row is the +Y pole; the centre column is seen looking along +Z, the
     * column at a quarter of the width along +X, at three quarters along −X, the left and
     * right edges along −Z. Texel (x, y) sits at u = (x + ½)/W, v = y/(H − 1), bilinear in
     * between. The map is importance-sampled (luminance · sin θ) for next-event estimation.
     * Read one from a file with {@code SceneLoader.readImage}.
     *
     * @param map           linear radiance, at least 1×2 pixels; negative and NaN values count as black
     * @param scale         factor on the radiance, finite and ≥ 0
     * @param rotateDegrees rotation of the map about +Y (right-handed), in degrees
     * @return this builder
     * @throws IllegalArgumentException if the map is too small or the scale or rotation is not finite
     */
    public Scene.Builder environmentMap(Image map, double scale, double rotateDegrees) {
        this.environment = mapOf(map, scale, rotateDegrees);
        return self();
    }

    static Environment mapOf(Image map, double scale, double rotateDegrees) {
        Objects.requireNonNull(map, "map");
        return Environment.map(map.width(), map.height(), map.rgb(), scale, rotateDegrees, "map");
    }

    /**
     * Adds a point light (glTF {@code KHR_lights_punctual} "point"): the irradiance it gives a
     * surface at distance d, facing it, is I/d². A delta light: only light sampling finds it.
     * @param position  where it is
     * @param intensity radiant intensity I, W/sr per channel, ≥ 0
     * @return this builder
     * @throws IllegalArgumentException if the position is not finite or the intensity negative
     */
    public Scene.Builder pointLight(Vector3dc position, Rgb intensity) {
        punctual.add(PunctualLight.point(position, intensity));
        return self();
    }

    /**
     * Adds a spot light (glTF "spot"): a point light whose intensity I is scaled by glTF's
     * falloff clamp((cd − cos outer) / (cos inner − cos outer), 0, 1)², cd the cosine between
     * {@code direction} and the way from the light to the lit point.
     *
     * @param position          where it is
     * @param direction         its axis, the direction it shines in (any length but zero)
     * @param intensity         radiant intensity I on the axis, W/sr per channel, ≥ 0
     * @param innerConeRadians  full intensity within this angle of the axis, ≥ 0
     * @param outerConeRadians  no light beyond this angle, ≥ inner, &gt; 0 and ≤ π/2
     * @return this builder
     * @throws IllegalArgumentException for angles out of range, a zero direction or a negative intensity
     */
    public Scene.Builder spotLight(Vector3dc position, Vector3dc direction, Rgb intensity, double innerConeRadians, double outerConeRadians) {
        punctual.add(PunctualLight.spot(position, direction, intensity, innerConeRadians, outerConeRadians));
        return self();
    }

    /**
     * Adds a directional light (glTF "directional"): parallel light, as from a distant sun.
     * @param direction  the direction the light travels (any length but zero)
     * @param irradiance irradiance E on a surface facing the light, W/m² per channel, ≥ 0
     * @return this builder
     * @throws IllegalArgumentException for a zero direction or a negative irradiance
     */
    public Scene.Builder directionalLight(Vector3dc direction, Rgb irradiance) {
        punctual.add(PunctualLight.directional(direction, irradiance));
        return self();
    }
}
