package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import gcnc.diag.Code;
import gcnc.diag.Phrase;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Plurals by ChoiceFormat (gcnc.tables.Plurals) in errors.csv and phrases.csv, in both languages. */
class PluralsTest {
    private static final ErrorMessages M = Tables.builtIn().messages();

    @Test
    void oneLaterBlockIsSingularAndSeveralArePlural() {
        assertEquals("1 later block has the same cause (line 10)",
                M.render(Code.E115_SAME_CAUSE, List.of("1", "10"), ErrorMessages.Lang.EN));
        assertEquals("3 later blocks have the same cause (lines 3, 4, 6)",
                M.render(Code.E115_SAME_CAUSE, List.of("3", "3, 4, 6"), ErrorMessages.Lang.EN));
        assertEquals("1 bloque posterior tiene la misma causa (línea 10)",
                M.render(Code.E115_SAME_CAUSE, List.of("1", "10"), ErrorMessages.Lang.ES));
        assertEquals("12000 bloques posteriores tienen la misma causa (líneas 3, 4, 6...)",
                M.render(Code.E115_SAME_CAUSE, List.of("12000", "3, 4, 6..."), ErrorMessages.Lang.ES));
    }

    @Test
    void aCountIsShownAsTheDiagnosticGivesItNeverGrouped() {
        assertEquals("the block has 1 motion but its DMC makes 10000 sequences",
                M.render(Code.byNumber(311), List.of("1", "10000"), ErrorMessages.Lang.EN));
        assertEquals("el bloque tiene 0 movimientos pero su DMC hace 1 secuencia",
                M.render(Code.byNumber(311), List.of("0", "1"), ErrorMessages.Lang.ES));
    }

    @Test
    void aPhraseChoosesToo() {
        assertEquals("expected 1 field but found 3",
                M.render(Code.E400_TABLE, List.of(Phrase.CSV_FIELD_COUNT.with(1, 3)), ErrorMessages.Lang.EN));
        assertEquals("se esperaban 4 campos pero hay 1",
                M.render(Code.E400_TABLE, List.of(Phrase.CSV_FIELD_COUNT.with(4, 1)), ErrorMessages.Lang.ES));
    }

    @Test
    void bothSpellingsOfAChoiceAndNoChoiceAtAll() {
        assertEquals("{0} block", Plurals.choose("{0,choice,0#{0} blocks|1#{0} block|1<{0} blocks}", List.of("1")));
        assertEquals("{0} blocks", Plurals.choose("{0;choice;0#{0} blocks|1#{0} block|1<{0} blocks}", List.of("0")));
        assertEquals("a {1} b", Plurals.choose("a {1} b", List.of("1")));
        // not a number: the last form (the plural)
        assertEquals("x blocks", Plurals.choose("x {0,choice,1#block|1<blocks}", List.of("many")));
        assertThrows(IllegalArgumentException.class, () -> Plurals.choose("{0,choice,1#a|1<b", List.of("1")));
    }

    @Test
    void noTemplateInTheTablesSaysOneWithAPluralNoun() {
        // a placeholder right before a plural noun is a count that can be 1 unless it is a choice
        // or one of the limits that are never 1 (caps, look-aheads, loop limits: listed here)
        java.util.Set<Integer> neverOne = new java.util.HashSet<>(java.util.Set.of(45, 103, 116, 137, 149, 153, 167,
                176, 202, 207, 208, 330, 340, 403, 710, 404, 422, 423, 503, 504, 627, 680, 681)); // 340: only above 2 counts; 710: the run past its five-million-block budget
        for (int n = 220; n < 240; n++) {
            neverOne.add(n); // the Galil model's limits: a value past a range of the controller, its bounds many counts
        }
        StringBuilder bad = new StringBuilder();
        for (Code c : Code.values()) {
            for (ErrorMessages.Lang lang : ErrorMessages.Lang.values()) {
                String t = M.template(c, lang);
                if (!neverOne.contains(c.number()) && !t.contains("choice")
                        && t.matches(".*\\{\\d} (blocks|lines|passes|errors|levels|motions|sequences|counts|fields"
                        + "|bloques|líneas|pasadas|errores|niveles|movimientos|secuencias|cuentas|campos)\\b.*")) {
                    bad.append(c.id()).append(' ').append(lang).append(": ").append(t).append('\n');
                }
            }
        }
        assertEquals("", bad.toString());
    }
}
