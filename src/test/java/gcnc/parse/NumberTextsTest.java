package gcnc.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import gcnc.ir.RawBlock;
import java.util.List;
import org.junit.jupiter.api.Test;

/** A program's repeated numbers are read into one String each, and every text read is the one written. */
class NumberTextsTest {

    private static String read(NumberTexts texts, String line, int from, int to) {
        return texts.text(line.toCharArray(), from, to);
    }

    @Test
    void aRepeatedNumberIsOneString() {
        NumberTexts texts = new NumberTexts();
        String first = read(texts, "G01 Z-40.5 F120.", 5, 10);
        String again = read(texts, "N20 Z-40.5", 5, 10);
        assertEquals("-40.5", first);
        assertSame(first, again);
    }

    /** More texts than slots: each is still the text written, whichever slot it met (none is mistaken for another). */
    @Test
    void everyTextIsTheOneWrittenWhateverItsSlot() {
        NumberTexts texts = new NumberTexts();
        for (int round = 0; round < 2; round++) {
            for (int i = 0; i < 5000; i++) {
                String written = String.format("%d.%03d", i / 7, i % 1000);
                String line = "X" + written + " ";
                assertEquals(written, read(texts, line, 1, line.length() - 1));
            }
        }
        // texts of equal hash are told apart by their characters ("Aa" and "BB" hash alike in Java)
        assertEquals("Aa", read(texts, "Aa", 0, 2));
        assertEquals("BB", read(texts, "BB", 0, 2));
        assertEquals("Aa", read(texts, "Aa", 0, 2));
    }

    @Test
    void theBlocksOfAProgramShareTheirRepeatedNumbersButNotTheirSequenceNumbers() {
        List<RawBlock> blocks = Parsed.of("N10 G01 Z2. F120.\nN10 G01 Z2. F120.\n").blocks();
        assertEquals(2, blocks.size());
        for (int w = 1; w < 4; w++) {
            assertSame(blocks.get(0).words().get(w).number(), blocks.get(1).words().get(w).number());
        }
        // N numbers do not repeat in a program: they are not kept (they would push the others out)
        assertNotSame(blocks.get(0).words().get(0).number(), blocks.get(1).words().get(0).number());
        assertEquals("10", blocks.get(1).words().get(0).number());
    }
}
