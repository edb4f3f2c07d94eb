package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --stats}: a cluster render's figures per member are JSON objects of numbers a tool can add up. */
class StatsFileTest {
    @TempDir
    Path dir;

    /**
     * The {@code members} of a stats file: per member its fields, numbers as {@link Number} (only
     * JSON numbers become one), booleans and strings as such; null when the file has no members.
     */
    static List<Map<String, Object>> members(Path file) throws IOException {
        try (JsonParser p = new JsonFactory().createParser(file.toFile())) {
            assertThat(p.nextToken()).isEqualTo(JsonToken.START_OBJECT);
            while (p.nextToken() == JsonToken.FIELD_NAME) {
                String name = p.currentName();
                JsonToken t = p.nextToken();
                if (!name.equals("members")) {
                    p.skipChildren();
                    continue;
                }
                assertThat(t).isEqualTo(JsonToken.START_ARRAY);
                List<Map<String, Object>> list = new ArrayList<>();
                while (p.nextToken() == JsonToken.START_OBJECT) {
                    Map<String, Object> member = new LinkedHashMap<>();
                    while (p.nextToken() == JsonToken.FIELD_NAME) {
                        String key = p.currentName();
                        JsonToken v = p.nextToken();
                        member.put(key, v.isNumeric() ? p.getNumberValue() : v.isBoolean() ? (Object) p.getBooleanValue() : p.getText());
                    }
                    list.add(member);
                }
                return list;
            }
            return null;
        }
    }

    private static final RenderStats STATS = new RenderStats(2.0, 96 * 64 * 12, 200_000, 12, 1, false, 0, 0, 3, 12, 12, 12, 0, List.of());
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withSize(96, 64).withSamplesPerPixel(12);

    @Test
    void eachMemberIsAnObjectOfNumbers() throws Exception {
        Path file = dir.resolve("stats.json");
        StatsFile.write(file, withMembers(STATS, List.of(
                new RenderStats.Member("127.0.0.1:5702", true, 1, 7, 30_000, 170_000, 170_007, 1.75, 0),
                new RenderStats.Member("127.0.0.1:5701", false, 2, 11, 43_728, 270_000, 270_011, 2.2, 3))), SETTINGS, 0.5, 0.1, 0);
        List<Map<String, Object>> members = members(file);
        assertThat(members).hasSize(2);
        Map<String, Object> first = members.get(0);
        assertThat(first.keySet()).containsExactly("member", "coordinator", "threads", "units", "samples", "bytes_sent",
                "bytes_received", "unit_seconds", "mean_unit_seconds", "lost_units");
        assertThat(first.get("member")).isEqualTo("127.0.0.1:5702");
        assertThat(first.get("coordinator")).isEqualTo(true);
        assertThat(((Number) first.get("mean_unit_seconds")).doubleValue()).isEqualTo(0.25);
        Map<String, Object> second = members.get(1);
        assertThat(second.get("coordinator")).isEqualTo(false);
        assertThat(((Number) second.get("threads")).intValue()).isEqualTo(2);
        assertThat(((Number) second.get("units")).longValue()).isEqualTo(11);
        assertThat(((Number) second.get("samples")).longValue()).isEqualTo(43_728);
        assertThat(((Number) second.get("bytes_sent")).longValue()).isEqualTo(270_000);
        assertThat(((Number) second.get("bytes_received")).longValue()).isEqualTo(270_011);
        assertThat(((Number) second.get("unit_seconds")).doubleValue()).isEqualTo(2.2);
        assertThat(((Number) second.get("lost_units")).longValue()).isEqualTo(3);
        long samples = members.stream().mapToLong(m -> ((Number) m.get("samples")).longValue()).sum();
        assertThat(samples).as("the members' samples add up to the render's").isEqualTo(STATS.samples());
    }

    @Test
    void aLocalRenderHasNoMembers() throws Exception {
        Path file = dir.resolve("local.json");
        StatsFile.write(file, STATS, SETTINGS, 0.5, 0.1, 0);
        assertThat(members(file)).isNull();
        assertThat(Files.readString(file)).contains("\"samples\"").doesNotContain("members");
    }

    private static RenderStats withMembers(RenderStats s, List<RenderStats.Member> members) {
        return new RenderStats(s.seconds(), s.samples(), s.rays(), s.samplesPerPixel(), s.threads(), s.cancelled(), s.invalidSamples(),
                s.threadIdleSeconds(), s.passes(), s.minSamplesPerPixel(), s.meanSamplesPerPixel(), s.maxSamplesPerPixel(), s.convergedFraction(), members);
    }
}
