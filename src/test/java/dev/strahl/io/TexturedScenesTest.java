package dev.strahl.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.io.obj.ObjReader;
import dev.strahl.material.Lambert;
import dev.strahl.material.Principled;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.TestScenes;
import dev.strahl.texture.ImageTexture;
import dev.strahl.texture.UvTransform;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Texture coordinates and image textures through the file formats: OBJ vt, MTL map_Kd, scene-file textures. */
class TexturedScenesTest {
    @TempDir
    Path dir;

    private Path png(String name, int w, int h) throws Exception {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                img.setRGB(x, y, (x * 40) << 16 | (y * 40) << 8 | 128);
            }
        }
        Path p = dir.resolve(name);
        ImageIO.write(img, "png", p.toFile());
        return p;
    }

    @Test
    void objTexCoordsInEveryFaceFormSplitVerticesWhereTheyDiffer() throws Exception {
        Path obj = Files.writeString(dir.resolve("a.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\nvn 0 0 1\n"
                + "f 1/1 2/2 3/3\nf 2/2/1 4/4/1 3/3/1\nf 1 2 4\n");
        var mesh = ObjReader.read(obj).mesh();
        float[] uv = mesh.uvs();
        assertThat(uv).isNotNull();
        assertThat(mesh.vertexCount()).isEqualTo(3 + 3 + 3);        // (p, t, n) triples: 1/1, 2/2, 3/3, 2/2/1, 4/4/1, 3/3/1, 1, 2, 4
        int[] idx = mesh.indices();
        assertThat(new float[] {uv[2 * idx[0]], uv[2 * idx[0] + 1], uv[2 * idx[1]], uv[2 * idx[1] + 1], uv[2 * idx[2]], uv[2 * idx[2] + 1]})
                .containsExactly(0, 0, 1, 0, 0, 1);
        assertThat(uv[2 * idx[4]]).isEqualTo(0.5f);
        assertThat(Float.isNaN(uv[2 * idx[6]])).isTrue();                // a vertex without vt
    }

    @Test
    void sceneFileTexturesAreLoadedOnceAndScaled() throws Exception {
        png("wood.png", 4, 2);
        Path scene = Files.writeString(dir.resolve("s.json"), """
                { "materials": {
                    "a": { "type": "diffuse", "albedo": { "texture": "wood.png", "uvScale": [4, 2] } },
                    "b": { "type": "principled", "baseColor": { "texture": "wood.png" }, "roughness": { "texture": "wood.png" } } },
                  "shapes": [
                    { "type": "triangles", "positions": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2], "uvs": [0, 0, 1, 0, 0, 1], "material": "a" },
                    { "type": "sphere", "center": [3, 0, 0], "radius": 1, "material": "b" } ] }
                """);
        Scene s = SceneLoader.load(scene);
        Material a = s.materials().get(0);
        var albedo = (ImageTexture) ((Lambert) TestScenes.bsdf(a)).albedo();
        assertThat(albedo.transform()).isEqualTo(UvTransform.of(4, 2, 0, 0));
        var b = (Principled) TestScenes.bsdf(s.materials().get(1));
        assertThat(((ImageTexture) b.baseColor()).bitmap()).isSameAs(albedo.bitmap());          // decoded once
        assertThat(albedo.bitmap().isSrgbDecoded()).isTrue();
        assertThat(((ImageTexture) b.roughness()).bitmap().isSrgbDecoded()).isFalse();                // data: the raw texels
        assertThat(((ImageTexture) b.roughness()).bitmap().srgbDecoded()).isSameAs(albedo.bitmap());
        assertThat(s.textureBytes()).isEqualTo(2L * 4 * 2 * 3 * 4);                             // the raw and the decoded image
    }

    @Test
    void aMissingTextureIsAWarningAndACorruptOneAnErrorNamingIt() throws Exception {
        Path scene = Files.writeString(dir.resolve("s.json"), """
                { "materials": { "a": { "type": "diffuse", "albedo": { "texture": "gone.png" } } },
                  "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "a" } ] }
                """);
        Scene s = SceneLoader.load(scene);
        assertThat(s.notes()).anyMatch(n -> n.startsWith("warning: texture file not found") && n.contains("gone.png"));
        assertThat(((Lambert) TestScenes.bsdf(s.materials().get(0))).albedo().isConstant()).isTrue();
        byte[] good = Files.readAllBytes(png("bad.png", 8, 8));
        Files.write(dir.resolve("bad.png"), java.util.Arrays.copyOf(good, good.length / 2));
        Files.writeString(scene, Files.readString(scene).replace("gone.png", "bad.png"));
        assertThatThrownBy(() -> SceneLoader.load(scene)).isInstanceOf(SceneException.class).hasMessageContaining("bad.png")
                .hasMessageNotContaining("\n");
    }

    @Test
    void mtlMapKdWithScaleAndOffsetAndPbrKeys() throws Exception {
        png("c.png", 2, 2);
        Files.writeString(dir.resolve("m.mtl"), "newmtl tex\nKd 0.5 0.5 0.5\nmap_Kd -s 2 3 1 -o 0.5 0.25 c.png\n"
                + "newmtl pbr\nKd 0.9 0.1 0.1\nPr 0.4\nPm 1\n");
        Path obj = Files.writeString(dir.resolve("a.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                + "usemtl tex\nf 1/1 2/2 3/3\nusemtl pbr\nf 1 3 2\n");
        Scene s = SceneLoader.load(obj);
        Material tex = s.materials().stream().filter(m -> m.name().equals("tex")).findFirst().orElseThrow();
        var albedo = (ImageTexture) ((Lambert) TestScenes.bsdf(tex)).albedo();
        assertThat(albedo.transform()).isEqualTo(UvTransform.of(2, 3, 0.5, 0.25));
        Material pbr = s.materials().stream().filter(m -> m.name().equals("pbr")).findFirst().orElseThrow();
        var p = (Principled) TestScenes.bsdf(pbr);
        assertThat(p.roughness().value(0, 0)).isEqualTo(0.4);
        assertThat(p.metallic().value(0, 0)).isEqualTo(1);
    }
}
