package dev.strahl.world;

import dev.strahl.material.Bsdf;
import dev.strahl.material.NullBsdf;
import dev.strahl.medium.Medium;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.Arrays;
import java.util.List;

/**
 * The participating media of a world and where they are: the media by id, for every material
 * index whether its surfaces bound media and which (interior: the side the geometric normal points
 * away from; exterior: the side it points to; −1 is vacuum), which material indices are invisible
 * ({@link NullBsdf}), and the medium the camera is in. The rule is Mitsuba 3's: a ray that leaves a
 * boundary travels in the medium of the side it leaves towards; a surface that bounds no media
 * leaves the ray in the medium it was in, so objects can stand inside fog. Immutable.
 */
public final class Media {
    /** No media, no invisible surfaces: a world of surfaces only. */
    public static final Media NONE = new Media(List.of(), List.of(), new int[0], new int[0], new boolean[0], -1, new Bsdf[0]);

    private final Medium[] media;
    private final String[] names;
    private final int[] interior, exterior;
    private final boolean[] boundary;
    private final boolean[] invisible;
    private final int camera;
    private final boolean any;

    /**
     * @param media    the media; their index is their id
     * @param names    their names, for messages and the checkpoint's fingerprint
     * @param interior per material index, the medium inside its surfaces (−1: vacuum)
     * @param exterior per material index, the medium outside them (−1: vacuum)
     * @param boundary per material index, whether its surfaces bound media at all
     * @param camera   the medium the camera is in (−1: vacuum)
     * @param bsdfs    the world's BSDF per material index (the {@link NullBsdf}s are the invisible surfaces)
     */
    public Media(List<Medium> media, List<String> names, int[] interior, int[] exterior, boolean[] boundary, int camera, Bsdf[] bsdfs) {
        if (interior.length != bsdfs.length || exterior.length != bsdfs.length || boundary.length != bsdfs.length || media.size() != names.size()) {
            throw new IllegalArgumentException("one interior, exterior and boundary flag per material, and a name per medium");
        }
        this.media = media.toArray(new Medium[0]);
        this.names = names.toArray(new String[0]);
        this.interior = interior.clone();
        this.exterior = exterior.clone();
        this.boundary = boundary.clone();
        this.camera = camera;
        this.invisible = new boolean[bsdfs.length];
        boolean nullSurfaces = false;
        for (int m = 0; m < bsdfs.length; m++) {
            invisible[m] = bsdfs[m] instanceof NullBsdf;
            nullSurfaces |= invisible[m];
            checkId(interior[m]);
            checkId(exterior[m]);
        }
        checkId(camera);
        this.any = this.media.length > 0 || nullSurfaces;
    }

    private void checkId(int id) {
        if (id < -1 || id >= media.length) {
            throw new IllegalArgumentException("medium " + id + " of " + media.length);
        }
    }

    /** Whether the world has media or invisible surfaces: then only the volumetric path tracer renders it. */
    public boolean any() {
        return any;
    }

    /** The medium of an id ≥ 0. */
    public Medium medium(int id) {
        return media[id];
    }

    /** The number of media. */
    public int count() {
        return media.length;
    }

    /** The medium the camera is in, −1 for vacuum. */
    public int camera() {
        return camera;
    }

    /** Whether surfaces of this material are invisible (a {@link NullBsdf}): paths and shadow rays pass them. */
    public boolean isInvisible(int material) {
        return material < invisible.length && invisible[material];
    }

    /**
     * The medium a ray is in after it leaves a surface of {@code material} in a direction whose
     * cosine with the surface's geometric normal (outward: as the winding or the sphere gives it)
     * is {@code cosOutward}: the interior for a direction into the surface (cosOutward &lt; 0),
     * else the exterior; {@code current} where the material bounds no media.
     */
    public int after(int material, int current, double cosOutward) {
        if (material >= boundary.length || !boundary[material]) {
            return current;
        }
        return cosOutward < 0 ? interior[material] : exterior[material];
    }

    /** Feeds the media and where they are into a checkpoint's fingerprint. */
    public void digest(MessageDigest md) {
        StringBuilder sb = new StringBuilder("media camera " + camera + "\n");
        for (int i = 0; i < media.length; i++) {
            sb.append(names[i]).append(' ').append(media[i]).append('\n');
        }
        sb.append(Arrays.toString(interior)).append(Arrays.toString(exterior)).append(Arrays.toString(boundary)).append('\n');
        md.update(sb.toString().getBytes(StandardCharsets.UTF_8));
        for (Medium m : media) {
            if (m instanceof dev.strahl.medium.GridMedium grid) {
                grid.digest(md);
            }
        }
    }
}
