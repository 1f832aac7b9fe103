package gcnc.check;

import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;
import gcnc.machine.Units;

/**
 * What the control runs without a word but the programmer may not have meant, judged from the
 * blocks the checker accepted (issue 17: an error only where the control stops; a warning where it
 * runs the block and the result may not be what was meant). One per checker, fed in program order:
 * <ul>
 * <li>a cut with tool offset 00 that a T word set ({@code T0100}, {@code T0}): the geometry offset
 *     is not applied (E646, once per such T word, at the first cut after it);</li>
 * <li>the feed mode changed (G98/G99, G94/G95) with no F: the F in force is read in the new unit,
 *     F0.2 mm/rev becoming 0.2 mm/min (E647, at the G word, once a cut reads it before a new F);</li>
 * <li>G96 without S after a G97 S: the S is read as the surface speed (E648, at the G96, once a cut
 *     runs at it before the next S);</li>
 * <li>a C-axis or live-tool M code ({@code axis_option} in the M table) makes a later C word a
 *     precise "not supported yet" (E650) instead of a word without meaning.</li>
 * </ul>
 */
final class Advisories {
    private final FunctionIndex functions;
    /** The T word that set tool offset 00 and its line, while no cut has been warned about; else null. */
    private Word offsetZero;
    private int offsetZeroLine;
    /** E647 waiting for the cut that reads the F in its new unit; null when none. */
    private Diagnostic feedMode;
    /** E648 waiting for the cut that runs at the S read as a surface speed; null when none. */
    private Diagnostic surfaceSpeed;
    /** The last C-axis or live-tool M code accepted, and its line; null before any. */
    private Word axisOption;
    private int axisOptionLine;

    Advisories(FunctionIndex functions) {
        this.functions = functions;
    }

    /** A copy for the other position of the block delete switch. */
    Advisories copy() {
        Advisories a = new Advisories(functions);
        a.offsetZero = offsetZero;
        a.offsetZeroLine = offsetZeroLine;
        a.axisOption = axisOption;
        a.axisOptionLine = axisOptionLine;
        a.feedMode = feedMode;
        a.surfaceSpeed = surfaceSpeed;
        return a;
    }

    /**
     * A C word in a program that has used a C-axis or live-tool M code: E650 at it (the block is
     * rejected by the caller). False when the block has no C word or no such code came before.
     */
    /** Whether a C-axis option code (M154, Fanuc's builder code) is in force: a C is then the axis, not a chamfer. */
    boolean cAxisOn() {
        return axisOption != null;
    }

    boolean cAxis(RawBlock b, Diagnostics out) {
        if (axisOption == null) {
            return false;
        }
        for (Word w : b.words()) {
            if (w.letter() == Letter.C) {
                out.error(Code.E650_C_AXIS_NOT_SUPPORTED, w.span(), w, axisOption.number(), axisOptionLine);
                return true;
            }
        }
        return false;
    }

    /** After an accepted block ({@code made}: what it does), with the draft that built it. */
    void accepted(BlockDraft d, CheckedBlock made, Diagnostics out) {
        int line = d.block.line();
        java.util.List<Word> ws = d.block.words();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            Word w = ws.get(at);
            if (w.letter() == Letter.M && !w.number().isEmpty()) {
                MFunction f = functions.m(w.code());
                if (f != null && f.role() == MRole.AXIS_OPTION) {
                    axisOption = w;
                    axisOptionLine = line;
                }
            }
        }
        feedMode(d, made, out);
        surfaceSpeed(d, made, out);
        if (d.has(Letter.T)) {
            if (d.next.toolOffset == 0) {
                offsetZero = d.word(Letter.T);
                offsetZeroLine = line;
            } else {
                offsetZero = null;
            }
        }
        if (offsetZero != null && d.next.toolOffset == 0 && MotionKind.cuts(made)) {
            out.report(Diagnostic.warning(Code.E646_CUT_WITHOUT_TOOL_OFFSET, d.blame(), offsetZero, offsetZeroLine));
            offsetZero = null; // once per T word: the next cuts are the same mistake
        }
    }

    /**
     * E648: a G96 without S after a G97 S reads that S as the surface speed (Eb04 sets it), at the
     * G96 when a cut comes before the next S (Fusion's Haas post writes the S a few lines later).
     */
    private void surfaceSpeed(BlockDraft d, CheckedBlock made, Diagnostics out) {
        if (d.has(Letter.S) || !d.next.css) {
            surfaceSpeed = null;
        } else if (d.g96 != null && !d.prior.css() && !Double.isNaN(d.prior.rpm())) {
            surfaceSpeed = Diagnostic.warning(Code.E648_CSS_TAKES_RPM, d.g96.span(), NumberText.plain(d.prior.rpm()),
                    d.next.units == Units.INCH ? "ft/min" : "m/min");
        }
        if (surfaceSpeed != null && MotionKind.cuts(made)) {
            out.report(surfaceSpeed);
            surfaceSpeed = null;
        }
    }

    /**
     * E647: the feed mode changed with an F in force and no new F. Reported at the G word when a cut
     * follows before any F (a G98 on a program's closing safe line, with no cut after it, reads no F).
     */
    private void feedMode(BlockDraft d, CheckedBlock made, Diagnostics out) {
        if (d.has(Letter.F)) {
            feedMode = null;
        } else if (d.prior.feedPerRev() != d.next.feedPerRev && !Double.isNaN(d.next.feed)) {
            Word g = null;
            for (Word w : d.block.words()) {
                GFunction f = w.letter() == Letter.G && !w.number().isEmpty() ? functions.g(w.code()) : null;
                if (f != null && (f.role() == GRole.FEED_PER_MINUTE || f.role() == GRole.FEED_PER_REV)) {
                    g = w;
                }
            }
            if (g != null) { // else a cycle's own block: not the program's words
                String length = d.next.units == Units.INCH ? "in" : "mm";
                feedMode = Diagnostic.warning(Code.E647_FEED_MODE_WITHOUT_F, g.span(), g,
                        NumberText.plain(d.next.feed), length + (d.prior.feedPerRev() ? "/rev" : "/min"),
                        length + (d.next.feedPerRev ? "/rev" : "/min"));
            }
        }
        if (feedMode != null && MotionKind.cuts(made)) {
            out.report(feedMode);
            feedMode = null;
        }
    }
}
