package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The interpreter's own number reader gives exactly what Double.parseDouble gives, or NaN for non-numbers. */
class DmcNumberTest {
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
                expected = text.matches("[-+]?\\.?") ? Double.NaN : Double.parseDouble(text);
            } catch (NumberFormatException e) {
                expected = Double.NaN;
            }
            assertEquals(expected, DmcInterpreter.number(" " + text + " "), text);
        }
    }

    @Test
    void nonNumbersAreNaN() {
        for (String bad : new String[] {"", " ", "-", ".", "1.2.3", "1-2", "1e3", "NaN", "0x10", "--1", "1 2"}) {
            assertTrue(Double.isNaN(DmcInterpreter.number(bad)), bad);
        }
        assertEquals(12345678901234567.0, DmcInterpreter.number("12345678901234567"));
    }
}
