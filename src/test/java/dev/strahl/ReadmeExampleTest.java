package dev.strahl;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The library example of the README is the body of src/it/embed's Embed.java, word for word,
 * and that program compiles against the library and renders its PNG. (The invoker run of
 * {@code mvn verify} builds the example project itself against the packaged artifact.)
 */
class ReadmeExampleTest {
    static final Path EXAMPLE = Path.of("src", "it", "embed", "src", "main", "java", "dev", "strahl", "examples", "embed", "Embed.java");

    @TempDir
    Path dir;

    @Test
    void theReadmeShowsTheExamplesCode() throws Exception {
        String readme = Files.readString(Path.of("README.md"));
        String section = readme.substring(readme.indexOf("## Using strahl as a library"));
        Matcher block = Pattern.compile("```java\n(.*?)```", Pattern.DOTALL).matcher(section);
        assertThat(block.find()).as("a java block in the library section").isTrue();
        assertThat(block.group(1).strip()).isEqualTo(exampleRegion().strip());
    }

    @Test
    void theExampleCompilesAgainstTheLibraryAndWritesItsPng() throws Exception {
        Path classes = Files.createDirectories(dir.resolve("classes"));
        // javac as a process: the test runs inside the module dev.strahl, which does not read java.compiler
        Path javac = Path.of(System.getProperty("java.home"), "bin", "javac");
        List<String> args = new ArrayList<>(List.of(javac.toString(), "-d", classes.toString(), "-Xlint:all"));
        String modulePath = System.getProperty("jdk.module.path");
        if (modulePath != null && !modulePath.isBlank()) {
            args.addAll(List.of("--module-path", modulePath, "--add-modules", "dev.strahl"));
        } else {
            args.addAll(List.of("-classpath", System.getProperty("java.class.path")));
        }
        args.add(EXAMPLE.toString());
        Process p = new ProcessBuilder(args).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertThat(p.waitFor()).as("javac: %s", output).isZero();
        Path png = dir.resolve("embed.png");
        try (URLClassLoader loader = new URLClassLoader(new URL[] {classes.toUri().toURL()}, getClass().getClassLoader())) {
            Method main = loader.loadClass("dev.strahl.examples.embed.Embed").getMethod("main", String[].class);
            main.invoke(null, (Object) new String[] {png.toString()});
        }
        BufferedImage img = ImageIO.read(png.toFile());
        assertThat(img.getWidth()).isEqualTo(160);
        assertThat(img.getHeight()).isEqualTo(120);
    }

    @Test
    void theExampleProjectHasStrahlsVersionSoThatItDependsOnTheStrahlBuiltWithIt() throws Exception {
        Pattern version = Pattern.compile("<artifactId>[^<]+</artifactId>\\s*<version>([^<]+)</version>");
        Matcher strahl = version.matcher(Files.readString(Path.of("pom.xml")));
        Matcher example = version.matcher(Files.readString(Path.of("src", "it", "embed", "pom.xml")));
        assertThat(strahl.find()).isTrue();
        assertThat(example.find()).isTrue();
        assertThat(example.group(1)).isEqualTo(strahl.group(1));
        assertThat(Files.readString(Path.of("src", "it", "embed", "pom.xml"))).contains("<version>${project.version}</version>");
        assertThat(Files.readString(Path.of("README.md"))).contains("<version>" + strahl.group(1) + "</version>");
    }

    /** The lines between the README markers, without the method body's indentation. */
    static String exampleRegion() throws Exception {
        List<String> lines = Files.readAllLines(EXAMPLE);
        int begin = lines.indexOf("        // README:begin");
        int end = lines.indexOf("        // README:end");
        assertThat(begin).isNotNegative();
        assertThat(end).isGreaterThan(begin);
        return lines.subList(begin + 1, end).stream().map(l -> l.startsWith("        ") ? l.substring(8) : l)
                .collect(Collectors.joining("\n"));
    }
}
