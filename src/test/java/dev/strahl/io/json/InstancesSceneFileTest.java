package dev.strahl.io.json;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.world.World;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The scene file's {@code groups} and shapes of type {@code instance}: read into one group and its
 * instances (each group's triangles stored once), written and read back the same, and every
 * misuse refused with one line naming the file and the line.
 */
class InstancesSceneFileTest {
    @TempDir
    Path dir;

    static final String MATERIALS = "\"materials\": { \"m\": { \"type\": \"diffuse\", \"albedo\": [0.5, 0.5, 0.5] },"
            + " \"lamp\": { \"type\": \"diffuse\", \"albedo\": [0, 0, 0], \"emission\": [5, 5, 5] } },\n";
    static final String TRIANGLE = "{ \"type\": \"triangles\", \"positions\": [0, 0, 0, 1, 0, 0, 0, 1, 0], \"indices\": [0, 1, 2], \"material\": \"m\" }";

    private Path write(String name, String text) throws Exception {
        return Files.writeString(dir.resolve(name), text);
    }

    @Test
    void theGoldenSceneHasOneGroupShownFiveTimes() throws Exception {
        Scene scene = SceneLoader.load(Path.of("src/test/resources/golden/instances.json"));
        World w = World.of(scene);
        assertThat(w.instances().count()).isEqualTo(5);
        assertThat(w.uniqueTriangles()).isEqualTo(2 + 320 + 12);
        assertThat(w.instancedTriangles()).isEqualTo(2 + 5 * (320 + 12));
    }

    @Test
    void aDescriptionWithGroupsIsWrittenAndReadBackTheSame() throws Exception {
        SceneDescription d = JsonSceneReader.parse(Path.of("src/test/resources/golden/instances.json"));
        assertThat(d.groups()).containsOnlyKeys("pile");
        Path copy = write("copy.json", SceneFileWriter.write(d));
        for (String mesh : new String[] {"instances-rock.obj", "instances-slab.obj"}) {
            Files.copy(Path.of("src/test/resources/golden", mesh), dir.resolve(mesh));
        }
        assertThat(JsonSceneReader.parse(copy)).isEqualTo(d);
    }

    private String error(String text) throws Exception {
        Path file = write("s.json", text);
        var e = catchThrowableOfType(SceneException.class, () -> SceneLoader.load(file));
        assertThat(e).as("an error").isNotNull();
        return e.getMessage().replace(file.toString(), "s.json");
    }

    @Test
    void anInstanceInsideAGroupIsRefusedAtItsLine() throws Exception {
        assertThat(error("{ " + MATERIALS + "\"groups\": { \"a\": [ " + TRIANGLE + " ],\n \"b\": [\n { \"type\": \"instance\", \"group\": \"a\" } ] },\n"
                + " \"shapes\": [ { \"type\": \"instance\", \"group\": \"b\" } ] }"))
                .isEqualTo("s.json:4: 'groups.b' holds an instance: groups do not nest (place instances in 'shapes')");
    }

    @Test
    void anUnknownGroupIsRefusedAtItsLine() throws Exception {
        assertThat(error("{ " + MATERIALS + "\"groups\": { \"a\": [ " + TRIANGLE + " ] },\n \"shapes\": [\n { \"type\": \"instance\",\n \"group\": \"tree\" } ] }"))
                .isEqualTo("s.json:5: unknown group 'tree' (define it under 'groups')");
    }

    @Test
    void anEmptyGroupAndAGltfFileInAGroupAreRefused() throws Exception {
        assertThat(error("{ " + MATERIALS + "\"groups\": {\n \"a\": [ ] },\n \"shapes\": [ " + TRIANGLE + " ] }"))
                .isEqualTo("s.json:3: 'groups.a' is empty: a group needs shapes");
        Files.copy(Path.of("scenes/gltf-showcase.glb"), dir.resolve("m.glb"));
        assertThat(error("{ " + MATERIALS + "\"groups\": { \"a\": [\n { \"type\": \"gltf\", \"file\": \"m.glb\" } ] },\n \"shapes\": [ " + TRIANGLE + " ] }"))
                .isEqualTo("s.json:3: 'groups.a' holds a glTF file: glTF instances its own meshes (place it in 'shapes')");
    }

    @Test
    void anEmitterInAGroupIsRefusedNamingTheGroupAndMaterial() throws Exception {
        String lamp = TRIANGLE.replace("\"m\"", "\"lamp\"");
        assertThat(error("{ " + MATERIALS + "\"groups\": { \"a\": [ " + lamp + " ] },\n \"shapes\": [ { \"type\": \"instance\", \"group\": \"a\" } ] }"))
                .isEqualTo("s.json: 'groups.a': emissive material 'lamp' in group 'a': instanced shapes cannot be lights"
                        + " (place the emitter in the scene itself)");
    }
}
