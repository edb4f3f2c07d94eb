package dev.strahl.io.obj;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.fail;

import dev.strahl.scene.SceneException;
import dev.strahl.image.Rgb;
import dev.strahl.testing.TestData;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class MtlReaderTest {

    @TempDir
    Path dir;

    private final List<String> warnings = new ArrayList<>();

    @Test
    void missingKeysTakeTheDocumentedDefaults() throws Exception {
        MtlMaterial m = read("newmtl bare\n").get("bare");
        assertThat(m).isEqualTo(new MtlMaterial("bare", Rgb.gray(0.8), Rgb.BLACK, Rgb.BLACK, 0, 1, 2));
        assertThat(MtlMaterial.defaultMaterial())
                .isEqualTo(new MtlMaterial("default", Rgb.gray(0.8), Rgb.BLACK, Rgb.BLACK, 0, 1, 2));
        assertThat(warnings).isEmpty();
    }

    @Test
    void readsEveryRenderedKey() throws Exception {
        MtlMaterial m = read("""
                newmtl glass
                Kd 0.1 0.2 0.3
                Ks 0.4 0.5 0.6
                Ke 17 12 4
                Ns 96.5
                Ni 1.5
                illum 7
                """).get("glass");
        assertThat(m).isEqualTo(new MtlMaterial("glass", new Rgb(0.1, 0.2, 0.3), new Rgb(0.4, 0.5, 0.6),
                new Rgb(17, 12, 4), 96.5, 1.5, 7));
        assertThat(m.isEmissive()).isTrue();
    }

    @Test
    void oneNumberIsGrey() throws Exception {
        MtlMaterial m = read("newmtl g\nKd 0.5\nKs 0.25\nKe 2\n").get("g");
        assertThat(m.kd()).isEqualTo(Rgb.gray(0.5));
        assertThat(m.ks()).isEqualTo(Rgb.gray(0.25));
        assertThat(m.ke()).isEqualTo(Rgb.gray(2));
    }

    @Test
    void toleratesCommentsIndentationTabsAndAnyKeyCase() throws Exception {
        Map<String, MtlMaterial> materials = read("# header\n"
                + " newmtl light\t\t\t# trailing tabs and a comment\n"
                + "\tKa 0.78 0.78 0.78 # White\n"
                + "    Ke 10 10 10\n"
                + "\tKs 0 0 0# no space before the comment\n"
                + "  kd 0.5 0.5 0.5\r\n"
                + "ILLUM 1\n"
                + "\n");
        assertThat(materials).containsOnlyKeys("light");
        MtlMaterial m = materials.get("light");
        assertThat(m.ke()).isEqualTo(Rgb.gray(10));
        assertThat(m.kd()).isEqualTo(Rgb.gray(0.5));
        assertThat(m.illum()).isEqualTo(1);
        assertThat(warnings).isEmpty();
    }

    @Test
    void materialsComeInFileOrderAndNamesMayContainSpaces() throws Exception {
        Map<String, MtlMaterial> materials = read("newmtl zeta\nnewmtl alpha\nnewmtl my material\nnewmtl beta\n");
        assertThat(materials.keySet()).containsExactly("zeta", "alpha", "my material", "beta");
    }

    @Test
    void ambientAndTransparencyKeysAreAcceptedSilently() throws Exception {
        read("newmtl a\nKa 1 1 1\nd 1\nTr 0\nTf 1 1 1\n");
        assertThat(warnings).isEmpty();
    }

    @Test
    void unknownKeysWarnOncePerKey() throws Exception {
        MtlMaterial m = read("newmtl a\nPs 0.5\nKd 0.2\nPc 1\nnewmtl b\nPs 0.1\n").get("a");
        assertThat(m.kd()).isEqualTo(Rgb.gray(0.2));
        assertThat(warnings).hasSize(2);
        assertThat(warnings.get(0)).startsWith(dir.resolve("t.mtl") + ": ").contains("unknown key 'Ps' (line 2): ignored");
        assertThat(warnings.get(1)).contains("'Pc' (line 4)");
    }

    @Test
    void unsupportedTextureMapsWarnOncePerFile() throws Exception {
        Map<String, MtlMaterial> m = read("newmtl a\nmap_Kd a.png\nmap_Bump -bm 2 n.png\nbump b.png\nnewmtl b\nmap_Kd c.png\n");
        assertThat(warnings).singleElement().asString()
                .contains("texture statement 'map_Bump' (line 3) is not supported (strahl reads map_Kd, map_Pr and map_Pm): ignored");
        assertThat(m.get("a").mapKd().file()).isEqualTo(dir.resolve("a.png").toAbsolutePath());
        assertThat(m.get("b").mapKd().file()).isEqualTo(dir.resolve("c.png").toAbsolutePath());
    }

    @Test
    void aRepeatedNameKeepsTheFirstDefinitionWithAWarning() throws Exception {
        Map<String, MtlMaterial> materials = read("newmtl a\nKd 1 0 0\nnewmtl b\nnewmtl a\nKd 0 1 0\n");
        assertThat(materials.keySet()).containsExactly("a", "b");
        assertThat(materials.get("a").kd()).isEqualTo(new Rgb(1, 0, 0));
        assertThat(warnings).singleElement().asString().contains("'a' (line 4) is defined again");
    }

    @Test
    void nonPositiveNiWarnsAndBecomesOne() throws Exception {
        assertThat(read("newmtl a\nNi 0.0000\n").get("a").ni()).isEqualTo(1);
        assertThat(warnings).singleElement().asString().contains("line 2").contains("'a'");
    }

    @Test
    void spectralAndXyzColoursAreIgnoredWithAWarning() throws Exception {
        assertThat(read("newmtl a\nKd 0.5\nKd spectral x.rfl\nKs xyz 1 1 1\n").get("a").kd()).isEqualTo(Rgb.gray(0.5));
        assertThat(warnings).hasSize(2);
    }

    @Test
    void anEmptyFileHasNoMaterials() throws Exception {
        assertThat(read("# only a comment\n")).isEmpty();
    }

    @Test
    void cornellOriginalMaterials() throws Exception {
        Map<String, MtlMaterial> materials = MtlReader.read(TestData.cornell("CornellBox-Original.mtl"), warnings);
        assertThat(materials.keySet()).containsExactly(
                "leftWall", "rightWall", "floor", "ceiling", "backWall", "shortBox", "tallBox", "light");
        assertThat(materials.get("leftWall").kd()).isEqualTo(new Rgb(0.63, 0.065, 0.05));
        assertThat(materials.get("light").ke()).isEqualTo(new Rgb(17, 12, 4));
        assertThat(materials.get("light").kd()).isEqualTo(Rgb.gray(0.78));
        assertThat(materials.values()).filteredOn(MtlMaterial::isEmissive).extracting(MtlMaterial::name)
                .containsExactly("light");
        assertThat(warnings).isEmpty();
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
        "newmtl a\\nKd 1 x 1                | 2 | bad number 'x' in 'Kd'",
        "newmtl a\\nKd 1 2                  | 2 | 'Kd' needs 1 or 3 numbers, got 2",
        "newmtl a\\nKs 1 2 3 4              | 2 | 'Ks' needs 1 or 3 numbers, got 4",
        "newmtl a\\nKe                      | 2 | 'Ke' needs 1 or 3 numbers, got 0",
        "newmtl a\\n\\nKd -0.5 0 0          | 3 | colour component '-0.5' in 'Kd' must be finite and >= 0",
        "newmtl a\\nKe Infinity 0 0         | 2 | colour component 'Infinity' in 'Ke' must be finite and >= 0",
        "newmtl a\\nNs -1                   | 2 | 'Ns' must be a finite number >= 0",
        "newmtl a\\nNs                      | 2 | 'Ns' needs 1 number, got 0",
        "newmtl a\\nNs 1 2                  | 2 | 'Ns' needs 1 number, got 2",
        "newmtl a\\nNi NaN                  | 2 | 'Ni' must be finite",
        "newmtl a\\nillum 11                | 2 | 'illum' must be an integer 0..10",
        "newmtl a\\nillum 2.5               | 2 | 'illum' must be an integer 0..10",
        "newmtl a\\nillum two               | 2 | bad number 'two' in 'illum'",
        "Kd 1 1 1\\nnewmtl a                | 1 | 'Kd' before any newmtl",
        "newmtl a\\nnewmtl   # no name      | 2 | newmtl without a material name",
    })
    void malformedInputIsASceneExceptionAtItsLine(String text, int line, String message) throws Exception {
        Path file = write(text.replace("\\n", "\n"));
        assertThatThrownBy(() -> MtlReader.read(file, warnings))
                .isInstanceOf(SceneException.class)
                .hasMessageStartingWith(file + ":" + line + ": ")
                .hasMessageContaining(message);
    }

    @Test
    void aBinaryFileIsNotAnMtlFile() throws Exception {
        Path file = dir.resolve("t.mtl");
        Files.write(file, new byte[] {'n', 'e', 'w', 0, 1, 2});
        assertThatThrownBy(() -> MtlReader.read(file, warnings)).isInstanceOf(SceneException.class)
                .hasMessage(file + ":1: not a text MTL file (NUL byte)");
    }

    @Test
    void mtlMaterialRefusesValuesNoRendererCouldUse() {
        Rgb grey = Rgb.gray(0.5);
        assertThatThrownBy(() -> new MtlMaterial("", grey, grey, grey, 1, 1, 2)).hasMessageContaining("name");
        assertThatThrownBy(() -> new MtlMaterial("a", new Rgb(-1, 0, 0), grey, grey, 1, 1, 2)).hasMessageContaining("kd");
        assertThatThrownBy(() -> new MtlMaterial("a", grey, grey, grey, -1, 1, 2)).hasMessageContaining("ns");
        assertThatThrownBy(() -> new MtlMaterial("a", grey, grey, grey, 1, 0, 2)).hasMessageContaining("ni");
        assertThatThrownBy(() -> new MtlMaterial("a", grey, grey, grey, 1, 1, 11)).hasMessageContaining("illum");
    }

    /** Random edits of a real MTL file: every outcome is a map of materials or a SceneException. */
    @Test
    void mutatedInputGivesMaterialsOrASceneExceptionNeverAnythingElse() throws Exception {
        String seed = Files.readString(TestData.cornell("CornellBox-Glossy.mtl"));
        String alphabet = "0123456789-+. \t\n#eExKdsNi\u0000\u00e9";
        var random = new SplittableRandom(3);
        for (int round = 0; round < 2000; round++) {
            var text = new StringBuilder(seed);
            for (int e = 1 + random.nextInt(6); e > 0 && text.length() > 0; e--) {
                int at = random.nextInt(text.length());
                switch (random.nextInt(3)) {
                    case 0 -> text.deleteCharAt(at);
                    case 1 -> text.insert(at, alphabet.charAt(random.nextInt(alphabet.length())));
                    default -> text.setLength(at);
                }
            }
            Path file = write(text.toString());
            try {
                MtlReader.read(file, new ArrayList<>());
            } catch (SceneException expected) {
                assertThat(expected.getMessage()).startsWith(file.toString());
            } catch (RuntimeException e) {
                fail("unexpected " + e + " for input:\n" + text, e);
            }
        }
    }

    private Path write(String text) throws IOException {
        Path file = dir.resolve("t.mtl");
        Files.writeString(file, text);
        return file;
    }

    private Map<String, MtlMaterial> read(String text) throws Exception {
        return MtlReader.read(write(text), warnings);
    }
}
