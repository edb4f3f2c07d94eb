package dev.strahl.io.json;

import com.fasterxml.jackson.core.JsonEncoding;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import dev.strahl.files.AtomicFile;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/**
 * Writes a JSON document for tools ({@code render --stats}, {@code bench --json}): pretty-printed,
 * through {@link AtomicFile}, so that a reader never sees half a file.
 */
public final class JsonFile {
    private JsonFile() {}

    /** Fills a generator. */
    @FunctionalInterface
    public interface Body {
        void write(JsonGenerator json) throws IOException;
    }

    public static void write(Path file, Body body) throws IOException {
        AtomicFile.write(file, out -> {
            JsonGenerator json = new JsonFactory().createGenerator(out, JsonEncoding.UTF8);
            json.disable(JsonGenerator.Feature.AUTO_CLOSE_TARGET).useDefaultPrettyPrinter();
            body.write(json);
            json.close();                              // flushes; AtomicFile closes the stream
            out.write(System.lineSeparator().getBytes(StandardCharsets.UTF_8));
        });
    }
}
