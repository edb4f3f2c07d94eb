package dev.strahl.io.json;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.io.mesh.MeshFiles;
import dev.strahl.io.obj.MtlMaterial;
import dev.strahl.io.SceneLoader;
import dev.strahl.io.obj.ObjModel;
import dev.strahl.io.obj.ObjReader;
import dev.strahl.scene.Scene;
import dev.strahl.scene.Transform;
import dev.strahl.image.Image;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.render.RenderSettings;
import dev.strahl.testing.Renders;
import java.nio.file.Path;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The Cornell Box scene files against the OBJ route: the OBJ loaded directly (plus, for the two
 * variants with analytic spheres, the same spheres added through the builder API) renders the
 * identical image, bit for bit, at the same camera and seed.
 */
class SceneFileRoutesTest {
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withSize(24, 24).withSamplesPerPixel(4).withSeed(3);

    @ParameterizedTest
    @ValueSource(strings = {"cornell-box", "cornell-empty-rg", "cornell-mirror", "cornell-sphere", "cornell-glossy"})
    void sceneFileAndObjRouteRenderTheSameImage(String name) throws Exception {
        Scene file = SceneLoader.load(Path.of("scenes", name + ".json"));
        Scene.Builder b = Scene.builder();
        MeshFiles.add(Path.of("scenes", name + ".obj"), null, Transform.IDENTITY, b);
        b.camera(file.camera());
        if (name.equals("cornell-sphere")) {
            b.addSphere(new Vector3d(-0.4214, 0.3321, -0.28), 0.32635, Material.mirror("leftSphere", Rgb.gray(0.95)));
            b.addSphere(new Vector3d(0.44584, 0.3321, 0.37674), 0.32635, Material.dielectric("rightSphere", 2.5));
        } else if (name.equals("cornell-glossy")) {
            b.addSphere(new Vector3d(0.56429, 0.32991, -0.50761), 0.316,
                    Material.glossy("sphere", new Rgb(0.486, 0.631, 0.663), Rgb.gray(0.7), 32));
        }
        Scene obj = b.build();
        assertThat(obj.materials()).isEqualTo(file.materials());
        Image a = Renders.render(file, SETTINGS);
        Image c = Renders.render(obj, SETTINGS);
        assertThat(a.rgb()).containsExactly(c.rgb());
        assertThat(a.mean()[0]).isPositive();
    }

    @Test
    void aSceneWrittenWithInlineTrianglesRendersLikeItsObj() throws Exception {
        Scene viaObj = SceneLoader.load(Path.of("scenes", "cornell-box.json"));
        ObjModel model = ObjReader.read(Path.of("scenes", "cornell-box.obj"));
        // One triangles shape per material, in the OBJ's material order, so that material indices agree.
        var materials = new java.util.LinkedHashMap<String, SceneDescription.MaterialSpec>();
        var shapes = new java.util.ArrayList<SceneDescription.ShapeSpec>();
        int[] idx = model.mesh().indices();
        for (int slot = 0; slot < model.materials().size(); slot++) {
            MtlMaterial m = model.materials().get(slot);
            materials.put(m.name(), new SceneDescription.Diffuse(SceneDescription.ColorParam.of(m.kd()), m.ke()));
            java.util.List<Integer> tri = new java.util.ArrayList<>();
            for (int t = 0; t < model.triangleMaterial().length; t++) {
                if (model.triangleMaterial()[t] == slot) {
                    tri.addAll(java.util.List.of(idx[3 * t], idx[3 * t + 1], idx[3 * t + 2]));
                }
            }
            shapes.add(new SceneDescription.TrianglesShape(model.mesh().positions(), tri.stream().mapToInt(Integer::intValue).toArray(),
                    null, null, m.name(), Transform.IDENTITY));
        }
        var d = new SceneDescription(viaObj.camera(), SceneSettings.NONE, materials, shapes, null);
        Path dir = java.nio.file.Files.createTempDirectory("inline");
        Path json = java.nio.file.Files.writeString(dir.resolve("inline.json"), SceneFileWriter.write(d));
        Scene inline = SceneLoader.load(json);
        assertThat(inline.materials()).isEqualTo(viaObj.materials());
        // Triangles are grouped by material here, so the BVH differs; the image agrees within float round-off of traversal order.
        Image a = Renders.render(viaObj, SETTINGS), c = Renders.render(inline, SETTINGS);
        double[] ma = a.mean(), mc = c.mean();
        for (int ch = 0; ch < 3; ch++) {
            assertThat(mc[ch]).isCloseTo(ma[ch], org.assertj.core.data.Percentage.withPercentage(0.5));
        }
    }
}
