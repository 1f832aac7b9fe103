package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.List;

/**
 * One Fanuc macro B statement line, read and run in one go (a line in a loop is read again each
 * time it runs): an assignment {@code #101 = [#1 + 2.5] * 2}, a block of words with variable or
 * expression values {@code G01 X#101 Z-[#2 + 1] F0.2}, {@code GOTO n}, {@code IF [a GT b] GOTO n},
 * {@code IF [..] THEN #1 = ..}, {@code WHILE [..] DO m}, {@code END m}, and the alarm
 * {@code #3000 = n (text)}. Spaces are ignored, {@code ( )} are comments, {@code [ ]} group.
 * What the line comes to is an {@link Outcome}; an error is reported at its column and the line
 * comes to nothing. Grammar and sources: docs/program-flow.md.
 */
final class MacroLine extends MacroExpression {
    /** What a line comes to. */
    sealed interface Outcome permits Words, Done, Jump, Loop, EndLoop {
        /** Which outcome it is, for a switch over every one: each record names its own. */
        Kind kind();

        enum Kind { WORDS, DONE, JUMP, LOOP, END_LOOP }
    }

    /** Words for the checker, their values worked out; {@code malformed}: the words before an error (reported). */
    record Words(List<Word> words, boolean malformed, int blockDelete) implements Outcome {
        public Kind kind() {
            return Kind.WORDS;
        }
    }

    /** Nothing to hand on: an assignment, an IF that does not hold, or an error already reported. */
    record Done() implements Outcome {
        public Kind kind() {
            return Kind.DONE;
        }
    }

    /** GOTO, or IF [..] GOTO: go to the block labelled N{@code label} when {@code taken} (the IF holds). */
    record Jump(long label, boolean taken, Span at, String written) implements Outcome {
        public Kind kind() {
            return Kind.JUMP;
        }

        /** The statement as messages show it. */
        String text() {
            return MacroCursor.clean(written);
        }
    }

    /** WHILE [..] DO id: whether the condition holds. */
    record Loop(boolean holds, int id, Span at, String written) implements Outcome {
        public Kind kind() {
            return Kind.LOOP;
        }

        String text() {
            return MacroCursor.clean(written);
        }
    }

    /** END id: back to the WHILE of loop id. */
    record EndLoop(int id, Span at, String written) implements Outcome {
        public Kind kind() {
            return Kind.END_LOOP;
        }

        String text() {
            return MacroCursor.clean(written);
        }
    }

    static final Done DONE = new Done();
    /** The largest alarm number #3000 takes (Fanuc: 0 to 200). */
    static final int MAX_ALARM = 200;
    /** The addresses that take a whole number (the parser's integer words, and P and L). */
    private static final String WHOLE = "GMNOSTPL";

    private final int line;
    private final Diagnostics diags;
    /** The line's block delete level (0: none). */
    private int level;
    /** The words of a block line read so far: handed on, malformed, when a later one fails. */
    private final List<Word> words = new ArrayList<>();

    private MacroLine(String s, int line, Variables vars, Diagnostics diags) {
        super(s, vars);
        this.line = line;
        this.diags = diags;
    }

    /** Runs a macro line: what it comes to, after reporting any error in it. */
    static Outcome run(RawBlock b, Variables vars, Diagnostics diags, Control.BlockDelete skip) {
        MacroLine m = new MacroLine(b.macro(), b.line(), vars, diags);
        try {
            return m.blockDelete(skip);
        } catch (Fault f) {
            diags.error(f.code, Span.of(b.line(), f.at + 1), f.args);
            return m.words.isEmpty() ? DONE : new Words(List.copyOf(m.words), true, m.level);
        }
    }

    /**
     * A block delete mark first ({@code /}, {@code /2}): with the switch on ({@code skip} ON) a
     * statement is skipped, while a block of words goes on with its mark (the checker follows both
     * positions of the switch for it, as for any '/' block); a control without block delete
     * ({@code NONE}) reports the '/' as E010, as the parser does.
     */
    private Outcome blockDelete(Control.BlockDelete skip) throws Fault {
        brackets();
        blank();
        if (peek() != '/') {
            return statement();
        }
        if (skip == Control.BlockDelete.NONE) {
            throw new Fault(Code.E010_SYNTAX, i, "'/'");
        }
        i++;
        level = 1;
        if (Character.isDigit(peek()) && peek() != '0') {
            level = peek() - '0';
            i++;
        }
        blank();
        boolean statement = peek() == '#' || keywordAhead("GOTO") || keywordAhead("IF") || keywordAhead("WHILE")
                || keywordAhead("END");
        if (statement && skip == Control.BlockDelete.ON) {
            return DONE;
        }
        return statement();
    }

    /** The N label a line starts with, or -1 (for GOTO's search). */
    static long label(String text) {
        MacroLine m = new MacroLine(text, 1, null, null);
        try {
            m.blank();
            if (m.labelAhead()) {
                m.i++;
                return FlowWords.digits(m.digits());
            }
        } catch (Fault f) {
            return -1;
        }
        return -1;
    }

    /** Whether the line is {@code END id} (for a WHILE whose condition does not hold). */
    static boolean isEnd(String text, int id) {
        MacroLine m = new MacroLine(text, 1, null, null);
        try {
            m.blank();
            if (m.labelAhead()) {
                m.i++;
                m.digits();
                m.blank();
            }
            return m.keyword("END") && m.loopId() == id;
        } catch (Fault f) {
            return false;
        }
    }

    /**
     * Brackets nest at most five deep, the brackets of functions and conditions included (FANUC
     * Series 16/18 lathe operator's manual, custom macro, "Bracket nesting": alarm 118 past it):
     * E010 at the sixth '['.
     */
    private void brackets() throws Fault {
        int depth = 0;
        boolean comment = false;
        for (int k = 0; k < s.length(); k++) {
            char c = s.charAt(k);
            if (comment || c == '(') {
                comment = c != ')';
            } else if (c == '[' && ++depth > 5) {
                throw new Fault(Code.E010_SYNTAX, k, "'[' (brackets nest at most five deep)");
            } else if (c == ']') {
                depth--;
            }
        }
    }

    private Outcome statement() throws Fault {
        blank();
        Word n = null;
        if (labelAhead()) {
            int at = i++;
            n = new Word(Letter.N, digits(), span(at));
            blank();
        }
        int start = i;
        if (keyword("GOTO")) {
            return goTo(start, true, start);
        }
        if (keyword("IF")) {
            boolean holds = bracketedCondition();
            blank();
            int then = i;
            if (keyword("GOTO")) {
                return goTo(then, holds, start);
            }
            if (keyword("THEN")) {
                if (holds) {
                    blank();
                    assignment();
                }
                return DONE;
            }
            throw syntax(i);
        }
        if (keyword("WHILE")) {
            boolean holds = bracketedCondition();
            blank();
            if (!keyword("DO")) {
                throw syntax(i);
            }
            int id = loopId();
            return end(new Loop(holds, id, span(start), text(start)));
        }
        if (keyword("END")) {
            int id = loopId();
            return end(new EndLoop(id, span(start), text(start)));
        }
        if (peek() == '#') {
            assignment();
            return DONE;
        }
        return words(n);
    }

    /**
     * The rest of a GOTO (its label, from {@code from}; {@code holds}: whether an IF before it holds)
     * as the jump of the statement that starts at {@code start}.
     */
    private Outcome goTo(int from, boolean holds, int start) throws Fault {
        long label = whole(expr(), from);
        return end(new Jump(label, holds, span(start), text(start)));
    }

    /** {@code #n = expr}; {@code #3000 = n (text)} is the program's alarm (E148). */
    private void assignment() throws Fault {
        int at = i;
        expect('#');
        long n = variable();
        blank();
        expect('=');
        Double v = expr();
        end(DONE);
        if (n == 3000) {
            // Fanuc 0i/16/18, custom macro, "Alarms": #3000 = n (ALARM MESSAGE), n from 0 to 200
            double number = v == null ? 0 : Math.rint(v);
            if (number < 0 || number > MAX_ALARM) {
                diags.error(Code.E682_MACRO_ALARM_NUMBER, span(at), written(v), MAX_ALARM);
                return;
            }
            diags.error(Code.E148_MACRO_ALARM, span(at), Long.toString((long) number), comment);
            return;
        }
        try {
            vars.write(n, v);
        } catch (Variables.Refused r) {
            throw new Fault(r.code, at, excerpt(at));
        }
    }

    /** A block of words; a value from a variable or expression becomes the number it comes to. */
    private Outcome words(Word label) throws Fault {
        List<Word> out = words;
        if (label != null) {
            out.add(label);
        }
        for (blank(); i < s.length() && peek() != ';' && peek() != '%'; blank()) {
            int at = i;
            Letter l = Character.isLetter(peek()) ? Letter.of(Character.toUpperCase(peek())) : null;
            if (l == null) {
                throw syntax(at);
            }
            i++;
            blank();
            char c = peek();
            char next = i + 1 < s.length() ? s.charAt(i + 1) : 0;
            boolean computed = c == '#' || c == '[' || (c == '-' || c == '+') && (next == '#' || next == '[');
            String number;
            if (computed) {
                Double v = unary();
                if (v == null) {
                    throw new Fault(Code.E146_MACRO_NO_VALUE, at, excerpt(at, i));
                }
                number = number(l, v, at);
            } else {
                number = literal();
                if (number.isEmpty()) {
                    throw new Fault(Code.E006_NUMBER_EXPECTED, at, l.name());
                }
            }
            out.add(new Word(l, number, span(at)));
        }
        return out.isEmpty() ? DONE : new Words(List.copyOf(out), false, level);
    }

    /** The number text of a computed word: whole for G M N O S T P L, else with a decimal point (a macro value is never read in least increments). */
    private static String number(Letter l, double v, int at) throws Fault {
        if (WHOLE.indexOf(l.name().charAt(0)) >= 0) {
            long r = Math.round(v);
            if (Math.abs(v - r) > 1e-6 || r < 0) {
                throw new Fault(Code.E013_INTEGER_EXPECTED, at, l.name());
            }
            return Long.toString(r);
        }
        return format(v);
    }

    /** A value as a word's number: at most 4 decimals, always a point ("352.", "-0.5"). */
    static String format(double v) {
        BigDecimal d = BigDecimal.valueOf(v).setScale(4, RoundingMode.HALF_UP).stripTrailingZeros();
        if (d.signum() == 0) {
            return "0.";
        }
        String t = d.toPlainString();
        return t.indexOf('.') < 0 ? t + "." : t;
    }

    /** DO and END take a loop number, 1 to 3. */
    private int loopId() throws Fault {
        blank();
        int at = i;
        String d = digits();
        long id = FlowWords.digits(d);
        if (id < 1 || id > 3) {
            throw syntax(at);
        }
        return (int) id;
    }

    /** The line must end here (a comment, ';' or '%' may follow). */
    private <T extends Outcome> T end(T outcome) throws Fault {
        blank();
        if (i < s.length() && peek() != ';' && peek() != '%') {
            throw syntax(i);
        }
        return outcome;
    }

    private Span span(int at) {
        return Span.of(line, at + 1);
    }
}
