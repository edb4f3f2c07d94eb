package dev.strahl.io.text;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class FastDecimalTest {

    @Test
    void fastDecimalParsingAgreesWithParseDouble() {
        var random = new SplittableRandom(7);
        for (int i = 0; i < 200_000; i++) {
            String text = randomDecimal(random);
            double fast = FastDecimal.parse(text, 0, text.length());
            if (!Double.isNaN(fast)) {
                assertThat(Double.doubleToRawLongBits(fast)).as(text)
                        .isEqualTo(Double.doubleToRawLongBits(Double.parseDouble(text)));
            }
        }
        assertThat(FastDecimal.parse("0.7250", 0, 6)).isEqualTo(0.725);
        assertThat(FastDecimal.parse("1e5", 0, 3)).as("exponents go to parseDouble").isNaN();
    }

    @Test
    void theByteOverloadGivesTheSameBitsAsTheStringOne() {
        var random = new SplittableRandom(11);
        int taken = 0;
        for (int i = 0; i < 200_000; i++) {
            String text = randomDecimal(random);
            // Inside a longer buffer, as PLY tokens are: the range must be respected
            byte[] bytes = (" 9" + text + "x ").getBytes(StandardCharsets.ISO_8859_1);
            double fromString = FastDecimal.parse(text, 0, text.length());
            double fromBytes = FastDecimal.parse(bytes, 2, 2 + text.length());
            assertThat(Double.doubleToRawLongBits(fromBytes)).as(text).isEqualTo(Double.doubleToRawLongBits(fromString));
            taken += Double.isNaN(fromBytes) ? 0 : 1;
        }
        assertThat(taken).as("most short decimals take the fast path").isGreaterThan(100_000);
        byte[] plain = "-12.5".getBytes(StandardCharsets.ISO_8859_1);
        assertThat(FastDecimal.parse(plain, 0, plain.length)).isEqualTo(-12.5);
    }

    @Test
    void whatIsNotAPlainDecimalIsLeftToTheSlowParser() {
        for (String text : new String[] {"", "-", "+", ".", "1.2.3", "1e5", "nan", "inf", "0x10", "1,5", "--1", "1 ",
            "1234567890123456", "0." + "0".repeat(22) + "1"}) {
            byte[] bytes = text.getBytes(StandardCharsets.ISO_8859_1);
            assertThat(FastDecimal.parse(text, 0, text.length())).as(text).isNaN();
            assertThat(FastDecimal.parse(bytes, 0, bytes.length)).as(text).isNaN();
        }
        assertThat(FastDecimal.parse("123456789012345", 0, 15)).as("15 significant digits are exact").isEqualTo(123456789012345.0);
        assertThat(FastDecimal.parse("000.5", 0, 5)).as("leading zeros are not significant").isEqualTo(0.5);
    }

    private static String randomDecimal(SplittableRandom random) {
        var s = new StringBuilder();
        if (random.nextInt(3) == 0) {
            s.append(random.nextBoolean() ? '-' : '+');
        }
        int intDigits = random.nextInt(10);
        int fracDigits = random.nextInt(random.nextBoolean() ? 8 : 25);
        for (int d = 0; d < intDigits; d++) {
            s.append((char) ('0' + random.nextInt(10)));
        }
        if (fracDigits > 0 || random.nextBoolean()) {
            s.append('.');
        }
        for (int d = 0; d < fracDigits; d++) {
            s.append((char) ('0' + random.nextInt(10)));
        }
        return s.toString();
    }
}
