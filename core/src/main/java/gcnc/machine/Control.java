package gcnc.machine;

import gcnc.ir.Letter;
import gcnc.machine.Units;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;

/**
 * What the words of a program mean and which rules apply: one folder of {@code tables/controls/}
 * (control.cfg, g_codes.csv, m_codes.csv; the format is in tables/controls/README.md). A machine
 * profile names its control. The thesis's own rules are those of the control {@code thesis-2004}.
 *
 * @param name              the control's name
 * @param description       one line for {@code gcnc tables}
 * @param letters           the address letters it reads (others: E004)
 * @param g                 its G table by code
 * @param m                 its M table by code
 * @param powerUp           the G functions in force at cycle start
 * @param powerUpUnits      G20/G21 at cycle start, when the control says (else the machine's)
 * @param powerUpTool       tool in the turret at cycle start
 * @param powerUpOffset     tool offset in force at cycle start (0 = none)
 * @param clampFromG50      an S needs a G50 S clamp first (E050, E041); else the machine's maximum
 * @param chuckByProgram    the program must close the chuck before a cut (E038 at the first cut)
 * @param increasingN       N must increase (E043); else a repeat is a warning (E114)
 * @param noPointLiteral    X42 is 42 mm; else 0.042 mm (least increments)
 * @param dwellPSeconds     G04 P is seconds (Haas); else milliseconds
 * @param bareG28          a G28 with no axis word: E030, both axes home (Haas), or nothing moves
 *                          with the warning E704 (Fanuc)
 * @param blockDelete       how a '/' block is treated
 * @param builderM          an M code not in the table is passed to the machine; else E012
 * @param cycleRetractMm    the 45-degree retract of G71/G72 roughing passes when the program gives
 *                          no R (Haas Setting 73, Fanuc parameter 5133), mm; NaN when not set
 * @param calls             how M98 names the program and its repeat count, and how deep calls nest
 * @param macros            the control runs Fanuc macro B ({@code #} variables, {@code [ ]}
 *                          expressions, IF/GOTO/WHILE); else a macro line is E111
 * @param peckRetractMm     the chip-breaking retract after each peck of G74/G75 when the program
 *                          gives no first block R, and the clearance above the last peck of a
 *                          G83 (Haas Setting 22, Fanuc parameter 5139), mm; NaN when not set
 * @param pocketWalls       a type II G71/G72 leaves its allowance along the cutting axis on every
 *                          wall of a pocket (Haas, "Troughs"); else such an allowance with a pocket
 *                          is E189 (Fanuc: W must be 0)
 * @param lineComments      a '(' comment ends at its ')' or at the end of its line, a '(' inside
 *                          it is text (Haas, Fanuc); else comments may span lines and nest is
 *                          error 54 (the thesis's control)
 * @param corners           how a G01 block asks for a chamfer or corner radius at its end
 * @param fanucDrilling     the drilling and tapping cycles (G83, G84) take Fanuc's words: R the
 *                          distance from the initial level to the R point, Q the peck in least
 *                          increments, K the repeats; else Haas's (R the R plane's Z, Q a length,
 *                          I J K the pecks)
 * @param drillRAbsolute    with Fanuc's words, R in absolute mode (G90) is the R point's Z, as the
 *                          Fusion fanuc post writes it (parameter 5102#6 RAB, systems B and C);
 *                          else R is the distance from the initial level (the 0i-TF manual's
 *                          default, and always in incremental mode)
 * @param cutFirstMovePositions a type I G71/G72 whose first contour move goes along the cutting
 *                          axis alone (Z for G71, X for G72) at the start's level takes it as a
 *                          positioning move, and roughs type I from where it ends (key
 *                          {@code cycle.type1_first_move = positions}: Haas, issue 31); else such a
 *                          first move is E155 (Fanuc alarm PS0065: Z in a type I G71's first block)
 * @param stop              what the control does at a program stop (M00, and M01 with the optional
 *                          stop switch on): the M codes it applies when the stop begins (keys
 *                          {@code stop.off}, {@code stop.optional}; docs/galil.md, "Program stops")
 * @param clampAboveLimit   an rpm S above the G50 (G92 on system B) S limit runs at the limit, with
 *                          the warning E280 (key {@code spindle_above_clamp = clamp}: Fanuc, Haas);
 *                          else it is E048 (the thesis's control, Table 5 error 48)
 */
public record Control(String name, String description, Set<Letter> letters, Map<Integer, GFunction> g,
                      Map<Integer, MFunction> m, List<GFunction> powerUp, Optional<Units> powerUpUnits,
                      int powerUpTool, int powerUpOffset, boolean clampFromG50, boolean chuckByProgram,
                      boolean increasingN, boolean noPointLiteral, boolean dwellPSeconds, BareG28 bareG28,
                      BlockDelete blockDelete, boolean builderM, double cycleRetractMm, Calls calls, boolean macros,
                      double peckRetractMm, boolean pocketWalls, boolean lineComments, Corners corners,
                      boolean fanucDrilling, boolean drillRAbsolute, ProgramStop stop, boolean cutFirstMovePositions,
                      boolean clampAboveLimit) {
    /**
     * A program stop (M00; M01 when the optional stop switch is on) as the control makes it: the
     * axes at rest, then {@code off} applied (Haas: M05 and M09, the spindle stopped and the coolant
     * off), then the wait for cycle start; at cycle start the control puts back what {@code off}
     * changed (the spindle, run up again before the next feed, and the coolant). Fanuc's CNC stops
     * only the program: what the spindle and coolant do is the machine builder's ladder.
     *
     * @param off      the M codes applied at the stop, in order (key {@code stop.off})
     * @param optional the optional stop switch's position as the program is compiled (key
     *                 {@code stop.optional}; {@code gcnc run --optional-stop}): on, M01 stops as M00
     */
    public record ProgramStop(List<Integer> off, boolean optional) {
        public ProgramStop {
            off = List.copyOf(off);
        }

        /** A control that says nothing: the program stops, nothing else changes. */
        public static final ProgramStop PROGRAM_ONLY = new ProgramStop(List.of(), false);
    }

    /** The same control with the optional stop switch {@code on} or off. */
    public Control withOptionalStop(boolean on) {
        if (on == stop.optional()) {
            return this;
        }
        return new Control(name, description, letters, g, m, powerUp, powerUpUnits, powerUpTool, powerUpOffset,
                clampFromG50, chuckByProgram, increasingN, noPointLiteral, dwellPSeconds, bareG28, blockDelete,
                builderM, cycleRetractMm, calls, macros, peckRetractMm, pocketWalls, lineComments, corners,
                fanucDrilling, drillRAbsolute, new ProgramStop(stop.off(), on), cutFirstMovePositions, clampAboveLimit);
    }

    /** Whether M code {@code code} stops the program here: M00 always, M01 when the optional stop switch is on. */
    public boolean stopsProgram(int code) {
        MFunction f = m.get(code);
        return f != null && (f.role() == MRole.STOP || f.role() == MRole.OPTIONAL_STOP && stop.optional());
    }

    /**
     * G01 chamfering and corner rounding (key {@code g01.corner}, docs/chamfer.md): none; Haas's
     * {@code ,C} and {@code ,R} at any angle, and I or K for a 90-degree chamfer; Fanuc T's
     * {@code C} (or I, K) and {@code R} for a 90-degree corner.
     */
    public enum Corners { NONE, COMMA, LETTERS }

    /** The block delete switch: none (a '/' is a syntax error), or its position as compiled. */
    public enum BlockDelete { NONE, OFF, ON }

    /** What a G28 with no axis word does (key {@code g28.bare}): E030, both axes home, or nothing moves (E704). */
    public enum BareG28 { ERROR, HOME, NOTHING }

    /**
     * Subprogram calls (keys {@code call.p} and {@code call.depth}).
     *
     * @param countInP a P of more than 4 digits is a repeat count and a 4-digit program number
     *                 (Fanuc: P21000 = O1000 twice); else P is the program number alone (Haas)
     * @param depth    how many calls may be in progress at once (the main program not counted)
     */
    public record Calls(boolean countInP, int depth) {
        public Calls {
            if (depth < 1) {
                throw new IllegalArgumentException("call depth is at least 1: " + depth);
            }
        }
    }

    public Control {
        letters = Set.copyOf(letters);
        g = java.util.Collections.unmodifiableMap(new TreeMap<>(g));
        m = java.util.Collections.unmodifiableMap(new TreeMap<>(m));
        powerUp = List.copyOf(powerUp);
    }

    public Collection<GFunction> allG() {
        return g.values();
    }

    public Collection<MFunction> allM() {
        return m.values();
    }

    /** The first G code of this control that does {@code role}, for messages ("G01"). */
    public Optional<GFunction> gFor(GRole role) {
        return g.values().stream().filter(f -> f.role() == role).findFirst();
    }

    /** The M code of this control that does {@code role} (Haas: CHUCK_CLOSE is M10). */
    public Optional<MFunction> mFor(MRole role) {
        return m.values().stream().filter(f -> f.role() == role).findFirst();
    }

    /**
     * Whether a program on this control can change its own flow (a subprogram call or return, or a
     * macro statement): if not, its blocks run as written and need no program-flow stage.
     */
    public boolean hasProgramFlow() {
        return macros || m.values().stream().anyMatch(f -> f.role() == MRole.CALL || f.role() == MRole.LOCAL_CALL
                || f.role() == MRole.RETURN);
    }

    /** How the program must end, for E052: "M30", or "M02 or M30". */
    public String endCodes() {
        List<String> ends = m.values().stream().filter(f -> f.role() == MRole.END).map(MFunction::name).toList();
        return ends.isEmpty() ? "M30" : String.join(" or ", ends);
    }
}
