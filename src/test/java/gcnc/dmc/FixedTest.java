package gcnc.dmc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The DMC reader's numbers: the value Double.parseDouble gives, none for non-numbers, and printed
 * back as they were written (trailing zeros kept).
 */
class FixedTest {
    private static double number(String s) {
        Fixed f = Fixed.parse(s, 0, s.length(), false);
        return f == null ? Double.NaN : f.value();
    }

    @Test
    void randomDecimalsReadExactlyAsJavaReadsThem() {
        Random rnd = new Random(11);
        for (int n = 0; n < 200_000; n++) {
            StringBuilder t = new StringBuilder();
            if (rnd.nextInt(4) == 0) {
                t.append(rnd.nextBoolean() ? '-' : '+');
            }
            int intDigits = rnd.nextInt(9);
            for (int i = 0; i < intDigits; i++) {
                t.append((char) ('0' + rnd.nextInt(10)));
            }
            if (rnd.nextBoolean()) {
                t.append('.');
                int decimals = rnd.nextInt(12);
                for (int i = 0; i < decimals; i++) {
                    t.append((char) ('0' + rnd.nextInt(10)));
                }
            }
            String text = t.toString();
            double expected;
            try {
                // more than 18 digits is no number a DMC line holds (a long's worth)
                expected = text.matches("[-+]?\\.?") || text.replaceAll("[^0-9]", "").length() > 18 ? Double.NaN
                        : Double.parseDouble(text);
            } catch (NumberFormatException e) {
                expected = Double.NaN;
            }
            assertEquals(expected == 0 ? 0.0 : expected, number(" " + text + " "), text); // -0 reads as 0
        }
    }

    @Test
    void nonNumbersAreNaN() {
        for (String bad : new String[] {"", " ", "-", ".", "1.2.3", "1-2", "1e3", "NaN", "0x10", "--1", "1 2"}) {
            assertTrue(Double.isNaN(number(bad)), bad);
        }
        assertEquals(12345678901234567.0, number("12345678901234567"));
        assertTrue(Double.isNaN(number("1234567890123456789")), "more than 18 digits");
    }

    @Test
    void printsAsWritten() {
        for (String t : new String[] {"3.0000", "-8.2132", "0", "180", "12345678901234567", "-0.0001", "0.5"}) {
            assertEquals(t, Fixed.of(t).toString());
        }
        assertEquals("-8.2132", Fixed.fourDecimals(-8.21319).toString());
        assertEquals("180", Fixed.fourDecimals(180).toString());
        assertEquals("0.0001", Fixed.fourDecimals(0.00005).toString());
        assertEquals("3.0000", Fixed.exactly(2.99999, 4).toString());
    }
}
