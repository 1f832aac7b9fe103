package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * tables/explain/ (gcnc explain, SARIF's help): every code a program can meet has its prose in
 * English and Spanish and an example, and each example really brings its code about when gcnc
 * checks it, or translates and simulates it, on the example's machine (as {@code gcnc check} or
 * {@code gcnc compile} does).
 */
class ExplainTest {
    static final Explanations EXPLAIN = Explanations.builtIn();

    /** Every code but the internal ones. */
    static Set<Code> reachable() {
        Set<Code> s = EnumSet.allOf(Code.class);
        s.removeAll(Explanations.INTERNAL.keySet());
        return s;
    }

    @Test
    void everyCodeAProgramCanMeetIsExplainedInBothLanguages() {
        for (ErrorMessages.Lang lang : ErrorMessages.Lang.values()) {
            Set<Code> missing = EnumSet.copyOf(reachable());
            missing.removeAll(EXPLAIN.explained(lang));
            assertEquals(Set.of(), missing, "no " + lang + " explanation in tables/explain/");
        }
        Set<Code> missing = EnumSet.copyOf(reachable());
        missing.removeAll(EXPLAIN.exemplified());
        assertEquals(Set.of(), missing, "no example in tables/explain/examples.md");
    }

    @Test
    void noInternalCodeIsExplainedAsIfAProgramCouldMeetIt() {
        for (Code c : Explanations.INTERNAL.keySet()) {
            assertTrue(EXPLAIN.prose(c, ErrorMessages.Lang.EN).isEmpty(), c + " is internal but explained");
            assertTrue(EXPLAIN.example(c).isEmpty(), c + " is internal but has an example");
        }
    }

    @Test
    void everyExampleTriggersItsCode() throws Exception {
        List<String> wrong = new ArrayList<>();
        java.util.Map<String, Session> sessions = new java.util.HashMap<>();
        for (Code c : EXPLAIN.exemplified()) {
            Explanations.Example e = EXPLAIN.example(c).orElseThrow();
            if (e.lines().isEmpty()) {
                continue; // everyExampleIsShort... holds the few to their reason
            }
            Session s = sessions.computeIfAbsent(e.machine() + "/" + e.control(), ExplainTest::open)
                    .withDialect(gcnc.galil.Dialect.Kind.of(e.dialect()));
            // check's findings and compile's: check warns where compile's simulation judges (E660 / E306)
            List<Diagnostic> found = new ArrayList<>(s.check(new StringReader(e.program())).diagnostics().sorted());
            found.addAll(s.compile(new StringReader(e.program()), Optional.of(s.simulation()), false,
                    line -> { }).diagnostics().sorted());
            if (found.stream().noneMatch(d -> d.code() == c)) {
                wrong.add(c.id() + " not met by its example; found " + found.stream().map(d -> d.code().id()).toList());
            }
        }
        assertEquals(List.of(), wrong, String.join("\n", wrong));
    }

    @Test
    void everyExampleIsShortAndShowsNoMoreThanTheFault() {
        for (Code c : EXPLAIN.exemplified()) {
            Explanations.Example e = EXPLAIN.example(c).orElseThrow();
            assertTrue(e.lines().isEmpty() != e.none().isEmpty(), c + ": an example or the reason there is none");
            assertTrue(e.lines().size() <= 6, c + ": " + e.lines().size() + " lines shown");
        }
    }

    /** {@code machine/control}: the profile, and another control for it when one is named. */
    private static Session open(String machineAndControl) {
        String[] mc = machineAndControl.split("/", -1);
        Session.Options o = Session.Options.defaults().withMachine(mc[0]);
        try {
            return Session.open(mc[1].isEmpty() ? o : o.withControl(mc[1]));
        } catch (TableException e) {
            throw new AssertionError(e);
        }
    }
}
