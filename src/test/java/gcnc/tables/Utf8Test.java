package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

class Utf8Test {
    private static byte[] bytes(String utf8, int... tail) {
        byte[] head = utf8.getBytes(StandardCharsets.UTF_8);
        byte[] out = java.util.Arrays.copyOf(head, head.length + tail.length);
        for (int i = 0; i < tail.length; i++) {
            out[head.length + i] = (byte) tail[i];
        }
        return out;
    }

    @Test
    void aByteOrderMarkIsDropped() throws Exception {
        assertEquals("a = 1\n", Utf8.decode("f", bytes("\uFEFFa = 1\n")));
    }

    @Test
    void aByteOrderMarkOnlyCountsAtTheStart() throws Exception {
        assertEquals("a\uFEFF", Utf8.decode("f", bytes("a\uFEFF")));
    }

    @Test
    void theFirstBadByteIsLocatedByLineAndCharacterColumn() {
        // Line 2 holds "año = " (6 characters, 7 bytes) before the Latin-1 byte 0xE9.
        TableException e = assertThrows(TableException.class, () -> Utf8.decode("f.csv", bytes("x\r\naño = ", 0xE9, 'A')));
        assertEquals("f.csv", e.path());
        assertEquals(2, e.diagnostic().span().line());
        assertEquals(7, e.diagnostic().span().column());
        assertEquals("byte 0xE9 is not UTF-8: save the file as UTF-8", e.english());
    }

    @Test
    void aSequenceCutShortAtTheEndIsAFault() {
        TableException e = assertThrows(TableException.class, () -> Utf8.decode("f", bytes("ab", 0xC3)));
        assertEquals(3, e.diagnostic().span().column());
    }
}
