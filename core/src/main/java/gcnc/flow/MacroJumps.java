package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.RawBlock;
import java.io.IOException;
import java.util.HashMap;
import java.util.Map;

/**
 * Where the macro statements GOTO, WHILE and END send a running program ({@link Frame}): the
 * block labelled N n (from the GOTO to the end, then from the start of what is held), into a loop
 * while its condition holds, after its END when it does not, back to its WHILE from its END. A
 * WHILE that turns more than {@link ProgramFlow#LOOP_LIMIT} times from one entry, or a GOTO that
 * jumps back that often, is an endless loop (E149); nowhere to go is E141. So is, at once, a loop
 * that comes round with every variable as it was the pass before: the flow of a macro program
 * depends on its variables alone (a value only the machine knows is E147, never read), so that pass
 * would run again for ever, as on the control.
 */
final class MacroJumps {
    private final Diagnostics diags;
    private final Variables vars;
    /** How many times each GOTO (program and index) has jumped back. */
    private final Map<String, Integer> jumpsBack = new HashMap<>();
    /** Each loop's variables when it last came round (or, for a WHILE, was entered): the same again is endless. */
    private final Map<String, Object> lastState = new HashMap<>();

    MacroJumps(Diagnostics diags, Variables vars) {
        this.diags = diags;
        this.vars = vars;
    }

    /** Whether the loop {@code key} comes round with every variable as it last did (and remembers them now). */
    private boolean unchanged(String key) {
        Object now = vars.state();
        return now.equals(lastState.put(key, now));
    }

    /** A loop as it last came round: its statement, where it is, and how many times it has run from its entry. */
    record Pass(String text, gcnc.diag.Span at, int passes) {
    }

    /** The loop that last came round (the innermost running), or null before any did. */
    private Pass last;

    /** The loop that last came round, for the run's budget (ProgramFlow, E710); null when none has. */
    Pass last() {
        return last;
    }

    /** GOTO n: the block labelled N n, searched from the GOTO to the end, then from the start. */
    void goTo(Frame f, MacroLine.Jump j, int at) throws IOException {
        int target = find(f.blocks, j.label(), at);
        if (target < 0) {
            diags.error(Code.E141_NO_JUMP_TARGET, j.at(), j.text(), "N" + j.label(), firstLine(f));
            return;
        }
        if (target <= at) {
            String key = System.identityHashCode(f.blocks) + ":" + at;
            int n = jumpsBack.merge(key, 1, Integer::sum);
            last = new Pass(j.text(), j.at(), n + 1);
            if (n > ProgramFlow.LOOP_LIMIT || unchanged(key)) {
                diags.error(Code.E149_MACRO_ENDLESS_LOOP, j.at(), j.text(), j.at().line(), Math.min(n, ProgramFlow.LOOP_LIMIT));
                return;
            }
        }
        f.next = target;
    }

    /** WHILE [..] DO m: on into the loop while it holds (up to the limit), else after its END m. */
    void loop(Frame f, MacroLine.Loop l, int at) throws IOException {
        int id = l.id();
        boolean again = f.cameBack && f.whileAt[id] == at;
        f.cameBack = false;
        f.whileAt[id] = at;
        f.turns[id] = again ? f.turns[id] + 1 : 1;
        if (again) {
            last = new Pass(l.text(), l.at(), f.turns[id]);
        }
        boolean holds = l.holds();
        String key = System.identityHashCode(f.blocks) + ":" + at;
        boolean same = false;
        if (holds && again) {
            same = unchanged(key);
        } else if (holds) {
            lastState.put(key, vars.state()); // entered: what its first pass starts from
        }
        if (holds && (f.turns[id] > ProgramFlow.LOOP_LIMIT || same)) {
            diags.error(Code.E149_MACRO_ENDLESS_LOOP, l.at(), l.text(), l.at().line(), Math.min(f.turns[id] - 1, ProgramFlow.LOOP_LIMIT));
            holds = false;
        }
        if (holds && again) {
            return;
        }
        // entering the loop, or leaving it: either way its END must follow (Fanuc alarm 124, missing END)
        int end = end(f, id, at);
        if (end < 0) {
            diags.error(Code.E141_NO_JUMP_TARGET, l.at(), l.text(), "END " + id, firstLine(f));
            f.whileAt[id] = -1;
            return;
        }
        if (!holds) {
            f.whileAt[id] = -1;
            f.next = end + 1;
        }
    }

    /** The index of the first {@code END id} after the WHILE at {@code at}, or -1. */
    private static int end(Frame f, int id, int at) throws IOException {
        for (int k = at + 1; ; k++) {
            RawBlock b = f.blocks.get(k);
            if (b == null) {
                return -1;
            }
            if (b.macro() != null && MacroLine.isEnd(b.macro(), id)) {
                return k;
            }
        }
    }

    /** END m: back to the WHILE of loop m. */
    void endLoop(Frame f, MacroLine.EndLoop e) throws IOException {
        int at = f.whileAt[e.id()];
        if (at < 0 || at < f.blocks.first()) {
            diags.error(Code.E141_NO_JUMP_TARGET, e.at(), e.text(), "WHILE [..] DO " + e.id(), firstLine(f));
            return;
        }
        f.next = at;
        f.cameBack = true;
    }

    /**
     * The index of the block labelled N{@code label}: searched from the block after {@code at} to
     * the end, then from the first block held up to {@code at}; -1 when there is none.
     */
    static int find(Blocks blocks, long label, int at) throws IOException {
        for (int k = at + 1; ; k++) {
            RawBlock b = blocks.get(k);
            if (b == null) {
                break;
            }
            if (label(b) == label) {
                return k;
            }
        }
        for (int k = blocks.first(); k <= at; k++) {
            RawBlock b = blocks.get(k);
            if (b != null && label(b) == label) {
                return k;
            }
        }
        return -1;
    }

    /** A block's N label: its first word's, or a macro line's leading N; -1 for none. */
    static long label(RawBlock b) {
        if (b.macro() != null) {
            return MacroLine.label(b.macro());
        }
        return !b.words().isEmpty() && b.words().get(0).letter() == gcnc.ir.Letter.N
                ? FlowWords.digits(b.words().get(0).number()) : -1;
    }

    /** The line of the first block a jump can reach. */
    static int firstLine(Frame f) throws IOException {
        RawBlock b = f.blocks.get(f.blocks.first());
        return b == null ? 1 : b.line();
    }
}
