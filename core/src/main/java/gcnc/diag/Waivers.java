package gcnc.diag;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * The waivers a shop signs in its program (docs/language.md, "Waivers"): {@code (GCNC ALLOW E642:
 * reason)} accepts E642 on its block (the block of its line, or of the next line with words when
 * the comment stands alone), {@code (GCNC ALLOW E642 FILE: reason)} on every line of its file from
 * its own on. The parser finds them ({@code gcnc.parse.WaiverComments}); {@link Diagnostics#waive}
 * applies them once, when the run's findings are final, so every front end gets them the same.
 * A waived finding is still reported, with the reason, and counted apart: it is neither an error
 * nor a warning of the run.
 *
 * <p>What cannot be waived: the simulator's errors (a collision, a move past a limit, a replay
 * that differs from the program: the E3xx errors), and the waivers' own findings (E670-E679).
 */
public final class Waivers {
    /** One waiver as written. */
    public record Waiver(Code code, boolean wholeFile, String reason, Span at, String file, int line) {
        /**
         * @param code      the code it names
         * @param wholeFile FILE: the rest of the file, else one block
         * @param reason    why the shop accepts it (never empty: a waiver without one is E670, not kept)
         * @param at        where the comment's '(' is
         * @param file      the file it is in (null: the program file)
         * @param line      the block's line (a FILE waiver: its own line, from which it applies)
         */
        public Waiver {
            java.util.Objects.requireNonNull(code);
            java.util.Objects.requireNonNull(reason);
            java.util.Objects.requireNonNull(at);
        }

        boolean covers(Diagnostic d) {
            return d.code() == code && java.util.Objects.equals(d.origin().file(), file)
                    && (wholeFile ? d.span().line() >= line : d.span().line() == line);
        }
    }

    /** The simulator's codes that are not errors (a note, warnings): they can be waived as any other. */
    private static final Set<Code> SIMULATOR_NOT_ERRORS = Set.of(Code.E316_SIM_NO_STOCK, Code.E321_SIM_STATION_ASSUMED,
            Code.E322_SIM_STATION_TIP_ONLY, Code.E330_CYCLE_MANY_PECKS, Code.E331_MAP_NOT_THIS_DMC,
            Code.E340_SIM_THREAD_PHASE);

    private final List<Waiver> all = new ArrayList<>();

    /** A waiver the parser read. */
    public void add(Waiver w) {
        all.add(w);
    }

    public boolean isEmpty() {
        return all.isEmpty();
    }

    List<Waiver> all() {
        return all;
    }

    /**
     * Whether findings with this code can never be waived: the simulator's errors (the machine
     * would move into a collision or a limit, or not as the program says) and the waivers' own.
     */
    public static boolean unwaivable(Code c) {
        return c.number() >= 300 && c.number() <= 399 && !SIMULATOR_NOT_ERRORS.contains(c) || waiverCode(c);
    }

    static boolean waiverCode(Code c) {
        return c.number() >= 670 && c.number() <= 679;
    }

    /** Found only by translating and simulating (the backend's and the simulator's codes): check cannot find them. */
    static boolean compileOnly(Code c) {
        int n = c.number();
        return n >= 200 && n <= 239 || n >= 250 && n <= 399;
    }
}
