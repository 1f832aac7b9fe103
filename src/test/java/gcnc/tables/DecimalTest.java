package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class DecimalTest {
    @Test
    void decimalNumbersAreRead() {
        assertEquals(12, Decimal.parse("12").getAsDouble());
        assertEquals(-0.5, Decimal.parse("-0.5").getAsDouble());
        assertEquals(0.25, Decimal.parse(".25").getAsDouble());
        assertEquals(3, Decimal.parse("+3.").getAsDouble());
        assertEquals(1e6, Decimal.parse("1E6").getAsDouble());
    }

    @Test
    void whatDoubleParseDoubleWouldAlsoTakeIsRefused() {
        for (String s : new String[] {"NaN", "Infinity", "-Infinity", "0x1p3", "1d", "2.5f", "1e999", "", " 1", "1,5"}) {
            assertTrue(Decimal.parse(s).isEmpty(), s);
        }
    }
}
