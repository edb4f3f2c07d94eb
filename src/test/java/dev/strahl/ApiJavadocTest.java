package dev.strahl;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.io.IOException;
import java.lang.module.ModuleDescriptor;
import java.lang.reflect.Modifier;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The API is small and fully documented: the exported packages (module-info.java) hold at most
 * {@value #MAX_TYPES} public types, nested ones counted; docs/architecture.md lists every one of
 * them; and javadoc with every doclint check, "missing" included (a comment on every public type
 * and member, every {@code @param}, {@code @return} and {@code @throws}), reports nothing for them.
 */
class ApiJavadocTest {
    static final int MAX_PACKAGES = 5;
    static final int MAX_TYPES = 32;

    @TempDir
    Path dir;

    /** The exported packages, e.g. "dev.strahl.scene". */
    static List<String> exportedPackages() {
        return ApiJavadocTest.class.getModule().getDescriptor().exports().stream().map(ModuleDescriptor.Exports::source).sorted().toList();
    }

    /** Every public type of the exported packages, nested ones included, by binary name. */
    static TreeSet<String> apiTypes() throws IOException {
        TreeSet<String> types = new TreeSet<>();
        for (String pkg : exportedPackages()) {
            try (Stream<Path> files = Files.list(sourceFolder(pkg))) {
                for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
                    String name = f.getFileName().toString().replace(".java", "");
                    Class<?> c;
                    try {
                        c = Class.forName(pkg + "." + name);
                    } catch (ClassNotFoundException e) {
                        continue;                      // package-info
                    }
                    addPublic(c, types);
                }
            }
        }
        return types;
    }

    private static void addPublic(Class<?> c, TreeSet<String> types) {
        if (!Modifier.isPublic(c.getModifiers())) {
            return;
        }
        types.add(c.getName().substring(c.getPackageName().length() + 1));
        for (Class<?> nested : c.getDeclaredClasses()) {
            addPublic(nested, types);
        }
    }

    private static Path sourceFolder(String pkg) {
        return Path.of("src", "main", "java").resolve(pkg.replace('.', File.separatorChar));
    }

    @Test
    void theApiIsAFewPackagesOfAFewTypes() throws Exception {
        assertThat(exportedPackages()).hasSizeLessThanOrEqualTo(MAX_PACKAGES);
        assertThat(apiTypes()).as("public types of the exported packages").hasSizeLessThanOrEqualTo(MAX_TYPES);
    }

    @Test
    void everyApiTypeHasCompleteJavadoc() throws Exception {
        String path = System.getProperty("jdk.module.path");
        String classPath = (path == null || path.isBlank() ? "" : path + File.pathSeparator) + System.getProperty("java.class.path");
        // The sources without module-info.java: in module mode javadoc 17 warns about the incubating
        // module that strahl requires statically, and no option turns that off.
        Path sources = dir.resolve("sources");
        Path main = Path.of("src", "main", "java");
        try (Stream<Path> all = Files.walk(main)) {
            for (Path f : all.filter(p -> p.toString().endsWith(".java") && !p.endsWith("module-info.java")).toList()) {
                Files.createDirectories(sources.resolve(main.relativize(f)).getParent());
                Files.copy(f, sources.resolve(main.relativize(f)));
            }
        }
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "javadoc").toString(),
                "-Xdoclint:all", "-quiet", "-d", dir.resolve("api").toString(), "-classpath", classPath,
                "-sourcepath", sources.toString()));
        cmd.addAll(exportedPackages());
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor()).as(out).isZero();
        assertThat(out.lines().filter(l -> l.contains("warning") || l.contains("error"))).as(out).isEmpty();
    }

    @Test
    void theArchitecturePageNamesEveryApiType() throws Exception {
        String page = Files.readString(Path.of("docs", "architecture.md"));
        for (String type : apiTypes()) {
            assertThat(page).as("docs/architecture.md names %s", type).contains("`" + type.replace('$', '.') + "`");
        }
    }
    /**
     * The build's javadoc (part of {@code mvn verify}) documents the exported packages only: every
     * other package must be in the pom's excludePackageNames, or javadoc reads it on the class path
     * (a new package using the Vector API then fails the build).
     */
    @Test
    void everyInternalPackageIsLeftOutOfTheBuildsJavadoc() throws IOException {
        String pom = Files.readString(Path.of("pom.xml"));
        int from = pom.indexOf("<excludePackageNames>") + "<excludePackageNames>".length();
        List<String> excluded = List.of(pom.substring(from, pom.indexOf("</excludePackageNames>", from)).split(":"));
        TreeSet<String> packages = new TreeSet<>();
        Path root = Path.of("src/main/java");
        try (Stream<Path> files = Files.walk(root)) {
            files.filter(f -> f.toString().endsWith(".java") && !f.endsWith("module-info.java"))
                    .forEach(f -> packages.add(root.relativize(f.getParent()).toString().replace(File.separatorChar, '.')));
        }
        packages.removeAll(exportedPackages());
        assertThat(excluded).as("pom.xml's excludePackageNames").containsAll(packages);
    }
}
