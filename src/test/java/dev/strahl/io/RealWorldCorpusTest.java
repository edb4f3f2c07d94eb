package dev.strahl.io;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.io.obj.MtlMaterial;
import dev.strahl.io.obj.ObjModel;
import dev.strahl.io.obj.ObjReader;
import dev.strahl.io.ply.PlyReader;
import dev.strahl.scene.Scene;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Files that real exporters wrote (3ds Max's Max2Obj, MilkShape 3D, Blender, VCGLIB), taken from
 * the regression data of two other loaders; origin, licence and the counts below in
 * src/test/resources/realworld/README.md. Each loads, with the triangle count its origin states
 * or an independent count (fan triangulation of every face, less the zero-area triangles that
 * strahl skips and says it skipped).
 */
class RealWorldCorpusTest {
    private static final Path DIR = Path.of("src/test/resources/realworld");

    @ParameterizedTest(name = "{0}: {1} triangles")
    @CsvSource({
        "assimp/regr01.obj, 2706, 4, 12",
        "assimp/spider.obj, 1312, 56, 4",
        "assimp/box_mat_with_spaces.obj, 12, 0, 1",
        "tinyobjloader/cornell_box.obj, 36, 0, 4",
        "tinyobjloader/usemtl-issue-68.obj, 400, 0, 2",
    })
    void objFilesLoadWithTheirTriangleCount(String file, int triangles, int degenerate, int materials) throws Exception {
        ObjModel model = ObjReader.read(DIR.resolve(file));
        assertThat(model.mesh().triangleCount()).isEqualTo(triangles);
        assertThat(model.materials()).hasSize(materials);
        assertThat(model.warnings()).noneMatch(w -> w.contains("unknown material") || w.contains("not found"));
        if (degenerate > 0) {
            assertThat(model.warnings()).anyMatch(w -> w.contains("skipped " + degenerate + " degenerate triangles"));
        }
        Scene scene = SceneLoader.load(DIR.resolve(file));           // and as a scene, the way the CLI loads it
        assertThat(scene.notes()).noneMatch(n -> n.contains("unknown material"));
    }

    @ParameterizedTest(name = "{0}: {1} triangles")
    @CsvSource({"assimp/cube_binary.ply, 12", "assimp/cube_uv.ply, 12"})
    void plyFilesLoadWithTheirTriangleCount(String file, int triangles) throws Exception {
        assertThat(PlyReader.read(DIR.resolve(file)).mesh().triangleCount()).isEqualTo(triangles);
    }

    /** Max2Obj (2001) wrote the name "Terraindæk" in Latin-1 into both files: read, matched, noted once per file. */
    @Test
    void latin1MaterialNamesOfAnOldExporterAreReadAndMatched() throws Exception {
        Path obj = DIR.resolve("assimp/regr01.obj");
        ObjModel model = ObjReader.read(obj);
        assertThat(model.materials()).extracting(MtlMaterial::name).contains("Terraind\u00e6k");
        assertThat(model.warnings()).filteredOn(w -> w.contains("read as Latin-1")).containsExactly(
                obj + ": not UTF-8 (first at line 4841): read as Latin-1",
                obj.resolveSibling("./regr01.mtl") + ": not UTF-8 (first at line 67): read as Latin-1");
    }
}
