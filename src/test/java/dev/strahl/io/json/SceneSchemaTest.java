package dev.strahl.io.json;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import com.networknt.schema.Error;
import com.networknt.schema.InputFormat;
import com.networknt.schema.Schema;
import com.networknt.schema.SchemaRegistry;
import com.networknt.schema.SpecificationVersion;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * docs/scene.schema.json, checked with a JSON Schema validator (networknt, draft 2020-12): the
 * shipped scenes and a scene with every key are valid, it knows exactly the keys the reader
 * knows, and what it refuses the reader refuses too.
 */
class SceneSchemaTest {
    private static final Path SCHEMA = Path.of("docs", "scene.schema.json");
    private static Schema schema;
    private static JsonNode schemaTree;

    @TempDir
    Path dir;

    @BeforeAll
    static void loadSchema() throws Exception {
        try (InputStream in = Files.newInputStream(SCHEMA)) {
            schema = SchemaRegistry.withDefaultDialect(SpecificationVersion.DRAFT_2020_12).getSchema(in);
        }
        schemaTree = JsonNode.parse(SCHEMA, Files.readString(SCHEMA));     // strahl's own line-keeping tree
    }

    private static List<Error> errors(String json) {
        return schema.validate(json, InputFormat.JSON);
    }

    @ParameterizedTest
    @ValueSource(strings = {"cornell-box", "cornell-empty-rg", "cornell-mirror", "cornell-sphere", "cornell-glossy"})
    void theShippedScenesAreValid(String name) throws Exception {
        assertThat(errors(Files.readString(Path.of("scenes", name + ".json")))).isEmpty();
    }

    @Test
    void aSceneWithEveryKeyIsValidAndSoIsWhatTheWriterWrites() throws Exception {
        assertThat(errors(SceneFileFormatTest.EVERY_KEY)).isEmpty();
        assertThat(errors(SceneFileWriter.write(JsonSceneReader.parse(Path.of("scenes", "cornell-glossy.json"))))).isEmpty();
    }

    @ParameterizedTest
    @ValueSource(strings = {"fog", "tint", "subsurface", "smoke"})
    void theMediaScenesAreValidAndSoIsWhatTheWriterWrites(String name) throws Exception {
        Path file = Path.of("src/test/resources/golden/media", name + ".json");
        assertThat(errors(Files.readString(file))).isEmpty();
        assertThat(errors(SceneFileWriter.write(JsonSceneReader.parse(file)))).isEmpty();
        assertThat(errors(MediaSceneFileTest.SCENE)).isEmpty();
    }

    @Test
    void theExampleOfTheFormatDocumentIsValidAndReadable() throws Exception {
        String doc = Files.readString(Path.of("docs", "scene-format.md"));
        String example = doc.substring(doc.indexOf("```json\n") + 8, doc.indexOf("```", doc.indexOf("```json\n") + 8));
        assertThat(example).contains("\"film\"", "\"integrator\"", "\"triangles\"", "\"transform\"");
        assertThat(errors(example)).isEmpty();
        Files.copy(Path.of("scenes", "cornell-empty-rg.obj"), dir.resolve("cornell-empty-rg.obj"));
        Files.copy(Path.of("scenes", "cornell-empty-rg.mtl"), dir.resolve("cornell-empty-rg.mtl"));
        Files.writeString(dir.resolve("bunny.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                + "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n0.1 0 0\n0 0.1 0\n3 0 1 2\n");
        SceneFile file = SceneFile.load(Files.writeString(dir.resolve("example.json"), example));
        assertThat(file.settings().samplesPerPixel()).isEqualTo(256);
    }

    @Test
    void theSchemaKnowsExactlyTheKeysOfTheReader() {
        JsonNode defs = get(schemaTree, "$defs");
        assertThat(keys(schemaTree)).isEqualTo(new TreeSet<>(JsonSceneReader.TOP_KEYS));
        assertThat(keys(get(defs, "camera"))).isEqualTo(new TreeSet<>(JsonSceneReader.CAMERA_KEYS));
        assertThat(keys(get(defs, "envmap"))).isEqualTo(new TreeSet<>(JsonSceneReader.ENVIRONMENT_KEYS.get("envmap")));
        assertThat(keys(get(defs, "film"))).isEqualTo(new TreeSet<>(JsonSceneReader.FILM_KEYS));
        assertThat(keys(get(defs, "integrator"))).isEqualTo(new TreeSet<>(JsonSceneReader.INTEGRATOR_KEYS));
        assertThat(byType(get(defs, "material"))).isEqualTo(sorted(JsonSceneReader.MATERIAL_KEYS));
        assertThat(byType(get(defs, "shape"))).isEqualTo(sorted(JsonSceneReader.SHAPE_KEYS));
        assertThat(byType(get(defs, "light"))).isEqualTo(sorted(SceneLights.KEYS));
        assertThat(byType(get(defs, "medium"))).isEqualTo(sorted(SceneFileMedia.KEYS));
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "{ \"shapes\": [] }",
        "{ \"camera\": { \"lookAt\": [0, 0, 0] }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"lights\": [ { \"type\": \"area\" } ], \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"lights\": [ { \"type\": \"point\", \"position\": [0, 1, 0] } ], \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"lights\": [ { \"type\": \"point\", \"position\": [0, 1, 0], \"intensity\": [1, -1, 1] } ], \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"lights\": [ { \"type\": \"spot\", \"position\": [0, 1, 0], \"direction\": [0, -1, 0], \"intensity\": [1, 1, 1], \"outerCone\": 120 } ], \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"lights\": [ { \"type\": \"directional\", \"direction\": [0, -1, 0], \"intensity\": [1, 1, 1] } ], \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"film\": { \"width\": 1.5 }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"integrator\": { \"maxDepth\": 0 }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"integrator\": { \"hemisphere\": \"stratified\" }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"integrator\": { \"photons\": 0 }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"integrator\": { \"photons\": 10000001 }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"integrator\": { \"photons\": 2.5 }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"integrator\": { \"photonRadius\": -0.5 }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"integrator\": { \"photonRadius\": \"auto\" }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"materials\": { \"m\": { \"type\": \"mirror\", \"emission\": [1, 1, 1] } }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"materials\": { \"m\": { \"type\": \"glossy\", \"specular\": [0.1, 0.1, 0.1] } }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"materials\": { \"m\": { \"type\": \"diffuse\", \"albedo\": [2, 0, 0] } }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.stl\" } ] }",
        "{ \"shapes\": [ { \"type\": \"cube\" } ] }",
        "{ \"shapes\": [ { \"type\": \"sphere\", \"center\": [0, 0], \"radius\": 1, \"material\": \"m\" } ] }",
        "{ \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\", \"transform\": [ { \"shear\": 1 } ] } ] }",
        "{ \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\", \"transform\": [ { \"scale\": 0 } ] } ] }",
        "{ \"shapes\": [ { \"type\": \"triangles\", \"positions\": [0, 0, 0], \"indices\": [0, 0, -1], \"material\": \"m\" } ] }",
        "{ \"environment\": [-1, 0, 0], \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"environment\": { \"type\": \"envmap\", \"file\": \"sky.png\" }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"environment\": { \"type\": \"sky\", \"file\": \"sky.hdr\" }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"environment\": { \"type\": \"envmap\", \"file\": \"sky.hdr\", \"scale\": -1 }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"camera\": { \"lookFrom\": [0, 0, 1], \"lookAt\": [0, 0, 0], \"aperture\": -0.1 }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"camera\": { \"lookFrom\": [0, 0, 1], \"lookAt\": [0, 0, 0], \"focusDistance\": 0 }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"media\": { \"m\": { \"type\": \"homogeneous\", \"sigmaT\": -1 } }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"media\": { \"m\": { \"type\": \"homogeneous\", \"sigmaT\": 1, \"albedo\": 1.5 } }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"media\": { \"m\": { \"type\": \"homogeneous\", \"sigmaT\": 1, \"g\": 1 } }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"media\": { \"m\": { \"type\": \"grid\", \"file\": \"a.raw\" } }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"media\": { \"m\": { \"type\": \"cloud\" } }, \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\" } ] }",
        "{ \"shapes\": [ { \"type\": \"mesh\", \"file\": \"a.obj\", \"interior\": 3 } ] }"})
    void whatTheSchemaRefusesTheReaderRefuses(String json) throws Exception {
        assertThat(errors(json)).as("schema errors").isNotEmpty();
        Files.writeString(dir.resolve("a.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        Path file = Files.writeString(dir.resolve("s.json"), json);
        assertThat(catchThrowableOfType(SceneException.class, () -> JsonSceneReader.parse(file))).as("reader error").isNotNull();
    }

    private static JsonNode get(JsonNode object, String key) {
        return object.object().get(key);
    }

    private static TreeSet<String> keys(JsonNode objectSchema) {
        return new TreeSet<>(get(objectSchema, "properties").object().keySet());
    }

    /** The keys of each branch of a oneOf, by the branch's "type" constant. */
    private static Map<String, Set<String>> byType(JsonNode union) {
        Map<String, Set<String>> out = new HashMap<>();
        for (JsonNode branch : get(union, "oneOf").array()) {
            out.put((String) get(get(get(branch, "properties"), "type"), "const").value, keys(branch));
        }
        return out;
    }

    private static Map<String, Set<String>> sorted(Map<String, Set<String>> m) {
        Map<String, Set<String>> out = new HashMap<>();
        m.forEach((k, v) -> out.put(k, new TreeSet<>(v)));
        return out;
    }
}
