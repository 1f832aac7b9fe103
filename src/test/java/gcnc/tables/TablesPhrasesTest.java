package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import gcnc.diag.Phrase;
import gcnc.machine.ProfileFile;
import gcnc.tables.ErrorMessages.Lang;
import java.util.List;
import org.junit.jupiter.api.Test;

/** E400 (a broken table or profile) reads in the message's language: each sentence is a {@link Phrase}. */
class TablesPhrasesTest {
    private static final ErrorMessages MESSAGES = Tables.builtIn().messages();

    private static String e400(String phrase, Lang lang) {
        return MESSAGES.render(Code.E400_TABLE, List.of(phrase), lang);
    }

    @Test
    void everyPhraseRendersInEnglishAndSpanish() {
        for (Phrase p : Phrase.values()) {
            String arg = p.with("a0", "a1", "a2", "a3", "a4", "a5", "a6");
            String en = e400(arg, Lang.EN);
            String es = e400(arg, Lang.ES);
            for (String text : List.of(en, es)) {
                assertFalse(text.isBlank(), p.name());
                assertFalse(text.contains("\u001E") || text.contains("\u001F") || text.contains(p.name()), p + ": " + text);
                assertFalse(text.matches("(?s).*\\{[0-9]+}.*"), p + ": a placeholder left in " + text);
            }
            assertNotEquals(en, es, p + " has no Spanish of its own");
        }
    }

    @Test
    void anUnknownKeyInSpanish() throws Exception {
        TableException e = assertThrows(TableException.class, () -> gcnc.machine.ProfileLoader.read(
                ProfileFile.parse("t.machine", java.nio.file.Files.readString(java.nio.file.Path.of(
                        "tables/machines/generic.machine")) + "foo = 1\n"), Tables.builtIn()));
        assertEquals("clave desconocida 'foo' (las claves están en docs/profiles.md y docs/simulator.md)",
                MESSAGES.render(e.diagnostic().code(), e.diagnostic().args(), Lang.ES));
        assertEquals("unknown key 'foo' (docs/profiles.md and docs/simulator.md list the keys)", e.english());
        assertTrue(e.getMessage().startsWith("t.machine:"), e.getMessage());
        assertTrue(e.getMessage().endsWith(": unknown key 'foo' (docs/profiles.md and docs/simulator.md list the keys)"),
                e.getMessage());
    }

    @Test
    void aPhraseInsideAPhraseIsInTheSameLanguage() {
        String inner = Phrase.LISTED_TWICE.with("G4");
        String outer = Phrase.CONTROL_FAULT.with("mine", "g_codes.csv:7:1", inner);
        assertEquals("control 'mine': g_codes.csv:7:1: G4 is listed twice", e400(outer, Lang.EN));
        assertEquals("controlador 'mine': g_codes.csv:7:1: G4 aparece dos veces", e400(outer, Lang.ES));
    }

    @Test
    void aPhraseThatCannotBeFoundStillPrints() {
        String unknown = "\u001ENO_SUCH_PHRASE_EVER\u001Fx\u001F3";
        assertEquals("NO_SUCH_PHRASE_EVER x 3", e400(unknown, Lang.ES));
        assertEquals("NO_SUCH_PHRASE_EVER x 3", ErrorMessages.english(Code.E400_TABLE, List.of(unknown)));
        assertEquals("plain text", ErrorMessages.english(Code.E400_TABLE, List.of("plain text")));
    }

    @Test
    void aFaultInTheTablesOwnNumbersIsSpanishToo() {
        assertEquals("'NaN' no es un número (lower)", e400(Phrase.NOT_A_NUMBER.with("NaN", "lower"), Lang.ES));
        assertEquals("el byte 0xFA no es UTF-8: guarde el archivo como UTF-8",
                e400(Phrase.NOT_UTF8.with("0xFA"), Lang.ES));
        assertEquals("'x.travel' necesita dos números 'a, b'", e400(Phrase.TWO_NUMBERS.with("x.travel", "a, b"), Lang.ES));
    }
}
