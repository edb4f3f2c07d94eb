package dev.strahl.testing;

import java.nio.file.Path;

/** Where the tests' data files live: inside the repository only, so that a bare clone passes. */
public final class TestData {
    private TestData() {}

    /**
     * McGuire &amp; Cardenas' Cornell Box variants (Williams College 2011, public domain):
     * {@code CornellBox-{Original,Empty-RG,Mirror,Sphere,Glossy}.obj/.mtl}.
     */
    public static final Path CORNELL = Path.of("src", "test", "resources", "cornell");

    /** One of the Cornell Box files, e.g. {@code cornell("CornellBox-Original.obj")}. */
    public static Path cornell(String file) {
        return CORNELL.resolve(file);
    }
}
