package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.codec.PfmReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** --checkpoint and --resume through the command line: a render continued later has the bits of one made in one go. */
class CheckpointCommandTest {
    private static final String CORNELL = RenderCommandTest.CORNELL;

    @TempDir
    Path dir;

    @Test
    void aRenderContinuedFromItsCheckpointIsBitIdenticalToOneInOneGo() throws Exception {
        Path once = dir.resolve("once.pfm");
        Path first = dir.resolve("first.pfm");
        Path resumed = dir.resolve("resumed.pfm");
        Path ck = dir.resolve("r.ck");
        assertThat(RenderCommandTest.render(CORNELL, once, "--spp", "20", "--seed", "4", "-q").code()).isZero();
        RenderCommandTest.Run a = RenderCommandTest.render(CORNELL, first, "--spp", "6", "--seed", "4", "--checkpoint", ck.toString(), "-q");
        assertThat(a.code()).as(a.err()).isZero();
        assertThat(ck).isRegularFile();
        RenderCommandTest.Run b = RenderCommandTest.render(CORNELL, resumed, "--spp", "20", "--seed", "4", "--threads", "1",
                "--resume", ck.toString());
        assertThat(b.code()).as(b.err()).isZero();
        assertThat(b.errLines().get(0)).startsWith("strahl: resuming " + ck + " at 6 spp");
        assertThat(Files.readAllBytes(resumed)).isEqualTo(Files.readAllBytes(once));
        assertThat(PfmReader.read(first).rgb()).isNotEqualTo(PfmReader.read(once).rgb());
        // the checkpoint moved on with the render: resuming it again at 20 spp renders nothing new
        RenderCommandTest.Run c = RenderCommandTest.render(CORNELL, dir.resolve("again.pfm"), "--spp", "20", "--seed", "4",
                "--resume", ck.toString());
        assertThat(c.code()).isZero();
        assertThat(c.err()).contains("resuming " + ck + " at 20 spp");
        assertThat(Files.readAllBytes(dir.resolve("again.pfm"))).isEqualTo(Files.readAllBytes(once));
    }

    @Test
    void aTimeLimitKeepsACheckpointToGoOnFrom() {
        Path ck = dir.resolve("t.ck");
        RenderCommandTest.Run r = RenderCommandTest.render(CORNELL, dir.resolve("t.png"), "--spp", "1000000", "--time-limit", "300ms",
                "--checkpoint", ck.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.err()).containsPattern("the time limit of 0.3 s ended the render at \\d+ of 1000000 spp; continue with --resume "
                + java.util.regex.Pattern.quote(ck.toString()));
        assertThat(ck).isRegularFile();
    }

    @Test
    void timeLimitsReadAsWritten() {
        assertThat(RenderOutcome.limitText(java.time.Duration.ofMillis(300))).isEqualTo("0.3 s");
        assertThat(RenderOutcome.limitText(java.time.Duration.ofSeconds(90))).isEqualTo("90 s");
        assertThat(RenderOutcome.limitText(java.time.Duration.ofMinutes(5))).isEqualTo("5:00");
        assertThat(RenderOutcome.limitText(java.time.Duration.ofMinutes(90))).isEqualTo("1:30:00");
    }
}
