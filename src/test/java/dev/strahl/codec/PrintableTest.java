package dev.strahl.codec;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** What a message may quote of a file: escaped, short, one line. */
class PrintableTest {
    @Test
    void textKeepsPrintableAsciiAndEscapesTheRest() {
        assertThat(Printable.text("abc")).isEqualTo("abc");
        assertThat(Printable.text("a\u001b[31mb\n\t\r\\")).isEqualTo("a\\x1b[31mb\\n\\t\\r\\\\");
        assertThat(Printable.text("caf\u00e9 \u00d7 \u202e")).isEqualTo("caf\\xe9 \\xd7 \\u202e");
        assertThat(Printable.quote("\u0000")).isEqualTo("'\\x00'");
    }

    @Test
    void textIsCutAfterAFewCharacters() {
        String longer = "x".repeat(Printable.QUOTE_LENGTH + 1);
        assertThat(Printable.text(longer)).isEqualTo("x".repeat(Printable.QUOTE_LENGTH) + "...");
        assertThat(Printable.text("x".repeat(Printable.QUOTE_LENGTH))).doesNotEndWith("...");
        assertThat(Printable.text("\u0001\u0002\u0003", 2)).isEqualTo("\\x01\\x02...");
    }

    @Test
    void bytesAreQuotedAsAsciiOrHex() {
        byte[] b = "glTX\u0002\u0000".getBytes(StandardCharsets.ISO_8859_1);
        assertThat(Printable.bytes(b, 0, 4)).isEqualTo("glTX...");
        assertThat(Printable.bytes(b, 2, 10)).isEqualTo("TX\\x02\\x00");
        assertThat(Printable.bytes(new byte[] {(byte) 0xff, '\\'}, 0, 2)).isEqualTo("\\xff\\x5c");
    }

    @Test
    void aLineKeepsPrintableUnicodeAndEscapesWhatIsInvisible() {
        assertThat(Printable.line("t.obj: bad 'caf\u00e9' \u00d7 2")).isEqualTo("t.obj: bad 'caf\u00e9' \u00d7 2");
        assertThat(Printable.line("a\nb\r\u2028c\u0085\u200bd")).isEqualTo("a\\nb\\r\\u2028c\\x85\\u200bd");
        assertThat(Printable.line("\ud83d\ude00 and a lone \ud83d")).isEqualTo("\ud83d\ude00 and a lone \\ud83d");
        assertThat(Printable.line(null)).isEqualTo("null");
        assertThat(Printable.line("y".repeat(5000))).hasSize(Printable.LINE_LENGTH + 3).endsWith("...");
    }
}
