package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.NoseSide;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;

/**
 * Thesis §4.2.2 action 14: modal G codes without motion or parameters. G40/G41/G42 (tool nose
 * radius compensation: the side is recorded here, the path offset by gcnc.check.NoseCompensation;
 * G41 to G42 or back without G40 is the warning E174), G96
 * (constant surface speed: S of this and later blocks is m/min or ft/min), and, added by gcnc for
 * real safe-start lines, G80 (canned cycle cancel) and the plane: G18 (ZX, the lathe's plane) is
 * accepted, G17 and G19 are E112; G61/G64 (exact stop mode, cutting mode) set the mode the planner
 * follows; a control's mode that changes nothing in the path (G22/G23: function
 * {@code mode_only}; Haas G103: {@code lookahead_limit}) is the note E700. Emits E016, E112, E174, E700. Writes next.css, next.nose, next.exactStopMode, d.g96.
 */
public final class Sa14ModalNoMotion implements SyntaxAction {
    /**
     * E700 (note): the mode changes nothing gcnc writes. E701 (warning) when the block gives the
     * mode values (G22's forbidden area X Z I K): the machine acts on them and gcnc does not check them.
     */
    private static void modeOnly(Word w, BlockDraft d, GFunction f, Diagnostics out) {
        StringBuilder values = new StringBuilder();
        for (Word v : d.block.words()) {
            switch (v.letter()) {
                case X, Z, U, W, I, K, P, Q, R -> values.append(values.length() == 0 ? "" : " ").append(v);
                default -> { }
            }
        }
        if (values.length() == 0) {
            noteMode(w, f, out);
        } else {
            // the block's words are the mode's (G22's area), not a move of the modal G00/G01
            if (d.oneShot == BlockDraft.NONE) {
                d.oneShot = GRole.MODE_ONLY.number();
                d.oneShotWord = w;
            }
            out.report(gcnc.diag.Diagnostic.warning(Code.E701_MODE_VALUES_NOT_CHECKED, w.span(), w, name(f), values));
        }
    }

    /** E700 at {@code w}: the mode {@code f} changes nothing in the path gcnc checks and writes. */
    private static void noteMode(Word w, GFunction f, Diagnostics out) {
        out.report(new gcnc.diag.Diagnostic(Code.E700_MODE_ONLY, gcnc.diag.Severity.NOTE, w.span(),
                java.util.List.of(w.toString(), name(f))));
    }

    /** "Stored stroke check on" as it reads after the code: "G22 stored stroke check on". */
    private static String name(GFunction f) {
        return f.english().isEmpty() ? "" : Character.toLowerCase(f.english().charAt(0)) + f.english().substring(1);
    }

    /** The most blocks Haas G103 limits the look-ahead to (Haas lathe manual, G103: "Range 0-15"). */
    public static final int MOST_LOOKAHEAD = 15;

    /**
     * Haas G103 (P n): the note E700, the path being the same for gcnc; the block's P is G103's, 0 to
     * 15 as the Haas takes it. A P after the G103 is held to that by its own syntax action (Sa02), one
     * before it here, after Table 6's P: the checker stops a block at its first error, and each word's
     * check where it is read keeps the note at the G103 in both orders.
     */
    private static void lookahead(Word w, BlockDraft d, GFunction f, Diagnostics out) {
        if (d.oneShot == BlockDraft.NONE) {
            d.oneShot = GRole.LOOKAHEAD_LIMIT.number(); // the block's P is G103's (Sa02: 0 to 15)
            d.oneShotWord = w;
        }
        for (Word p : d.block.words()) {
            if (p == w) {
                break; // a P after the G103: Sa02's
            }
            if (p.letter() == gcnc.ir.Letter.P && p.code() > MOST_LOOKAHEAD) {
                d.fail(out, Code.E009_PARAMETER_TOO_LARGE, p.span(), p.letter(), p.number(), MOST_LOOKAHEAD);
            }
        }
        noteMode(w, f, out);
    }

    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        GFunction f = d.functions.g(w.code());
        if (!d.claimG(f.group(), w, out)) {
            return;
        }
        if (f.role() == GRole.PLANE_XY || f.role() == GRole.PLANE_YZ) {
            d.fail(out, Code.E112_PLANE_NOT_ZX, w.span(), w);
        } else if (f.role() == GRole.NOSE_COMP_LEFT || f.role() == GRole.NOSE_COMP_RIGHT) {
            NoseSide side = f.role() == GRole.NOSE_COMP_LEFT ? NoseSide.LEFT : NoseSide.RIGHT;
            NoseSide before = d.prior.nose();
            if (before != NoseSide.OFF && before != side) {
                // Fanuc changes sides in offset mode without an alarm: a warning, and the
                // compensation ends before this block and starts again on the other side (NoseCompensation)
                String was = before == NoseSide.LEFT ? "G41" : "G42";
                out.report(gcnc.diag.Diagnostic.warning(Code.E174_NOSE_SIDE_CHANGE, w.span(), w, was));
            }
            d.next.nose = side;
        } else if (f.role() == GRole.NOSE_COMP_CANCEL) {
            d.next.nose = NoseSide.OFF;
        } else if (f.role() == GRole.CSS) {
            d.next.css = true;
            d.g96 = w;
        } else if (f.role() == GRole.EXACT_STOP_MODE || f.role() == GRole.CUTTING_MODE) {
            // G61 until G64: every move of this block and the next ends at rest (the planner ends
            // its sequence after each); the path is the same, only the corners are not blended
            d.next.set(f.role());
        } else if (f.role() == GRole.LOOKAHEAD_LIMIT) {
            lookahead(w, d, f, out);
        } else if (f.role() == GRole.MODE_ONLY) {
            // G22/G23: the control's stored stroke check; the travel gcnc checks is the profile's,
            // so the path is the same either way (docs/language.md)
            modeOnly(w, d, f, out);
        }
    }
}
