package gcnc.flow;

import gcnc.diag.Code;
import java.util.HashMap;
import java.util.Map;

/**
 * The macro B variables of one run, as far as they can be known before the machine runs:
 * #0 (always vacant), the locals #1-#33 (vacant at the start; M98 shares them with its caller,
 * a macro call G65 gives the called program a level of its own, {@link #enter}), and the common
 * #100-#199 and kept #500-#999 that this program has set. A common or kept variable read before
 * the program sets it holds what an earlier program or the operator left, and every system
 * variable (#1000 and up: signals, offsets, clocks, modal state, positions) is the machine's:
 * reading one is E147, never a guess. A value is a double; null is vacant.
 */
final class Variables {
    /** The locals of the level in force: #1-#33 at [1]..[33]. */
    private Double[] local = new Double[LOCALS];
    /** The levels of the macro calls' callers, innermost first. */
    private final java.util.ArrayDeque<Double[]> callers = new java.util.ArrayDeque<>();
    private final Map<Integer, Double> set = new HashMap<>();
    /** The size of a level: #0 unused, #1-#33. */
    static final int LOCALS = 34;

    /** A macro call begins: a new level of locals, {@code arguments} (#1-#33, null vacant), until {@link #leave}. */
    void enter(Double[] arguments) {
        callers.push(local);
        local = arguments.clone();
    }

    /** The macro call's program returned: its caller's locals again. */
    void leave() {
        local = callers.pop();
    }

    /** Thrown for a variable that cannot be read or written before the machine runs; the line reports it. */
    static final class Refused extends Exception {
        final Code code;

        Refused(Code code) {
            super(null, null, false, false);
            this.code = code;
        }
    }

    /**
     * Every variable's value now, as a value that equals another taken when they were all the same:
     * a loop that comes round to them unchanged will run the same pass again, and again
     * ({@link MacroJumps}, E149 at once instead of at the run's budget).
     */
    Object state() {
        return java.util.List.of(java.util.Arrays.asList(local.clone()), new HashMap<>(set));
    }

    /** The value of #n, null when vacant. */
    Double read(long n) throws Refused {
        if (n == 0) {
            return null;
        }
        if (n >= 1 && n <= 33) {
            return local[(int) n];
        }
        if (kept(n) && set.containsKey((int) n)) {
            return set.get((int) n);
        }
        throw new Refused(Code.E147_MACRO_RUN_TIME_ONLY);
    }

    /** Sets #n (#3000, the alarm, is the line's own business). */
    void write(long n, Double v) throws Refused {
        if (n >= 1 && n <= 33) {
            local[(int) n] = v;
        } else if (kept(n)) {
            set.put((int) n, v);
        } else {
            throw new Refused(Code.E111_MACRO_NOT_SUPPORTED_YET);
        }
    }

    private static boolean kept(long n) {
        return n >= 100 && n <= 199 || n >= 500 && n <= 999;
    }
}
