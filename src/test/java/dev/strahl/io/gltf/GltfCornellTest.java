package dev.strahl.io.gltf;

import static dev.strahl.io.gltf.GltfWriter.map;
import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.io.SceneLoader;
import dev.strahl.io.obj.MtlMaterial;
import dev.strahl.io.obj.ObjModel;
import dev.strahl.io.obj.ObjReader;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import dev.strahl.testing.Golden;
import dev.strahl.testing.Renders;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.joml.Matrix4d;
import org.joml.Quaterniond;
import org.joml.Vector3d;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Cornell Box written as glTF — a node hierarchy (a root moved, rotated and scaled, one child
 * per material whose vertices are stored in the root's coordinates), the camera as a glTF camera,
 * Lambertian walls as principled materials with KHR_materials_specular {@code specularFactor} 0,
 * the light as an emissive material (emissiveFactor × emissiveStrength) — renders like
 * scenes/cornell-box.json.
 *
 * <p>Tolerance: both are rendered at {@value #SIZE}×{@value #SIZE}, {@value #SPP} spp with
 * different seeds; the mean luminance of every visible face of at least {@value #MIN_PIXELS} pixels
 * must agree within {@value #TOLERANCE} (relative). Two renders of the scene file with different
 * seeds agree within that (the noise floor, a test of its own); a back wall whose albedo is 5 %
 * higher fails, so the comparison sees a wrong material, a missing light strength or a misplaced camera.
 */
class GltfCornellTest {
    static final int SIZE = 64;
    static final int SPP = 256;
    static final double TOLERANCE = 0.025;
    /** Faces smaller than this many pixels are too noisy to judge at this sample count. */
    static final int MIN_PIXELS = 64;

    @TempDir
    static Path dir;

    static Scene reference;
    static Image referenceImage;
    static List<Golden.Region> regions;

    @BeforeAll
    static void renderTheReference() throws Exception {
        reference = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        regions = Golden.faceRegions(reference, SIZE, SIZE).stream().filter(r -> r.pixels().length >= MIN_PIXELS).toList();
        referenceImage = Renders.render(reference, settings(1));
    }

    static RenderSettings settings(long seed) {
        return RenderSettings.defaults().withSize(SIZE, SIZE).withSamplesPerPixel(SPP).withSeed(seed);
    }

    /** scenes/cornell-box.obj/.mtl as a glTF asset; {@code albedoScale} brightens the back wall (for the mutation test). */
    static GltfWriter cornell(double albedoScale) throws Exception {
        ObjModel obj = ObjReader.read(Path.of("scenes/cornell-box.obj"));
        GltfWriter w = new GltfWriter();
        // the root: moved, turned 90° about y and scaled by 2; children hold vertices in its coordinates
        Quaterniond q = new Quaterniond().rotateY(Math.PI / 2);
        Matrix4d root = new Matrix4d().translationRotateScale(0.5, 1, -0.25, q.x, q.y, q.z, q.w, 2, 2, 2);
        Matrix4d toLocal = new Matrix4d(root).invert();
        float[] p = obj.mesh().positions();
        int[] idx = obj.mesh().indices();
        int[] materialOf = obj.triangleMaterial();
        List<Object> children = new ArrayList<>();
        for (int m = 0; m < obj.materials().size(); m++) {
            List<Integer> local = new ArrayList<>();
            List<Float> positions = new ArrayList<>();
            for (int t = 0; t < materialOf.length; t++) {
                if (materialOf[t] != m) {
                    continue;
                }
                for (int k = 0; k < 3; k++) {
                    int v = idx[3 * t + k];
                    Vector3d x = toLocal.transformPosition(new Vector3d(p[3 * v], p[3 * v + 1], p[3 * v + 2]));
                    positions.add((float) x.x);
                    positions.add((float) x.y);
                    positions.add((float) x.z);
                    local.add(local.size());
                }
            }
            if (local.isEmpty()) {
                continue;
            }
            float[] pos = new float[positions.size()];
            for (int i = 0; i < pos.length; i++) {
                pos[i] = positions.get(i);
            }
            int material = w.add("materials", material(obj.materials().get(m), albedoScale));
            int mesh = w.mesh(pos, local.stream().mapToInt(Integer::intValue).toArray(), material);
            children.add(w.add("nodes", map("name", obj.materials().get(m).name(), "mesh", mesh)));
        }
        double s = Math.sqrt(0.5);
        w.rootNode(map("name", "box", "translation", List.of(0.5, 1, -0.25), "rotation", List.of(0, s, 0, s), "scale", List.of(2, 2, 2),
                "children", children));
        w.add("cameras", map("type", "perspective", "perspective", map("yfov", Math.toRadians(40), "aspectRatio", 1.0, "znear", 0.01)));
        w.rootNode(map("name", "camera", "camera", 0, "translation", List.of(0, 1, 3.9)));
        w.root.put("extensionsUsed", List.of("KHR_materials_specular", "KHR_materials_emissive_strength"));
        return w;
    }

    private static Map<String, Object> material(MtlMaterial mtl, double albedoScale) {
        Rgb kd = mtl.kd();
        double scale = mtl.name().equals("backWall") ? albedoScale : 1;
        Map<String, Object> ext = map("KHR_materials_specular", map("specularFactor", 0));
        Map<String, Object> m = map("name", mtl.name(), "pbrMetallicRoughness",
                map("baseColorFactor", List.of(kd.r() * scale, kd.g() * scale, kd.b() * scale, 1), "metallicFactor", 0, "roughnessFactor", 1),
                "extensions", ext);
        Rgb ke = mtl.ke();
        if (ke != null && !ke.isBlack()) {
            double strength = ke.max();
            m.put("emissiveFactor", List.of(ke.r() / strength, ke.g() / strength, ke.b() / strength));
            ext.put("KHR_materials_emissive_strength", map("emissiveStrength", strength));
        }
        return m;
    }

    @Test
    void theGltfCornellBoxRendersLikeTheSceneFile() throws Exception {
        Scene gltf = SceneLoader.load(cornell(1).writeGlb(dir.resolve("cornell.glb")));
        assertThat(gltf.camera().lookFrom()).isEqualTo(reference.camera().lookFrom());
        assertThat(gltf.notes()).noneMatch(n -> n.contains("studio"));
        Image image = Renders.render(gltf, settings(2));
        String differences = Golden.differences(image, referenceImage, regions, TOLERANCE, 1);
        System.out.printf("glTF Cornell Box vs scene file: worst face %.2f %%%n", 100 * Golden.worstRegionError(image, referenceImage, regions));
        assertThat(differences).isEmpty();
    }

    @Test
    void theSceneFileAgainstItselfWithAnotherSeedIsWithinTheTolerance() {
        Image again = Renders.render(reference, settings(2));
        System.out.printf("scene file, seeds 1 and 2: worst face %.2f %%%n", 100 * Golden.worstRegionError(again, referenceImage, regions));
        assertThat(Golden.differences(again, referenceImage, regions, TOLERANCE, 1)).isEmpty();
        assertThat(regions).hasSizeGreaterThanOrEqualTo(6);
    }

    @Test
    void theComparisonSeesABackWallFivePercentBrighter() throws Exception {
        Scene brighter = SceneLoader.load(cornell(1.05).writeGlb(dir.resolve("brighter.glb")));
        Image image = Renders.render(brighter, settings(2));
        assertThat(Golden.differences(image, referenceImage, regions, TOLERANCE, 1)).contains("region");
    }
}
