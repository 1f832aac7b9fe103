package gcnc.check;

import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Motion;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.List;

/**
 * Which words of a block ask for a G01 chamfer or corner rounding, on the control's form
 * ({@code g01.corner}, docs/chamfer.md): Haas {@code ,C} {@code ,R} at any angle, C and R without
 * the comma the same, and I/K for 90 degrees; Fanuc T C, R and I/K for 90 degrees and the direct
 * drawing {@code ,C} {@code ,R} at any angle. C, R, I and K are corner words only on a G01 (on
 * G02/G03 they are the arc's); a comma word on a control without corners is E604, an R on its
 * G01 E025 (the block runs without it), two corners in one block E608. {@code ,A} is
 * {@link AngleLine}'s. For {@link CornerInsertion}.
 */
final class CornerWords {
    /**
     * What a block asks for: the word, chamfer or round, its size (program units, no sign), and
     * whether it is a 90-degree form (every form but Haas's comma words). {@link #FAILED}: the
     * block's corner words were wrong, which was reported; the block runs without them.
     */
    record Request(Word word, boolean round, double size, boolean square, ModalState taken) {
        static final Request FAILED = new Request(null, false, 0, false);

        Request(Word word, boolean round, double size, boolean square) {
            this(word, round, size, square, null);
        }

        /**
         * The block was refused for its corner word, the error reported: nothing runs, and the
         * checker takes the state {@code taken} past it (the block as if the word were struck out).
         */
        static Request refused(ModalState taken) {
            return new Request(null, true, 0, false, taken);
        }

        String name() {
            return word.toString();
        }

        /** The sign the word was written with: -1, or +1 when it has none. */
        double sign() {
            return word.number().startsWith("-") ? -1 : 1;
        }
    }

    /** The checker, to look only: this class returns what it finds and commits nothing. */
    private final Lookahead host;

    /** (made while the checker is made: its profile is read when a block comes) */
    CornerWords(Lookahead host) {
        this.host = host;
    }

    /** Whether the block has a word that may ask for a corner on this control (a comma word; C, R, I, K). */
    boolean mayAsk(RawBlock b) {
        Control.Corners form = host.profile().control().corners();
        java.util.List<Word> ws = b.words();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            Word w = ws.get(at);
            Letter l = w.letter();
            if (w.comma() || form != Control.Corners.NONE && (l == Letter.I || l == Letter.K)
                    || l == Letter.C && !host.cAxisOn() || l == Letter.R) {
                return true;
            }
        }
        return false;
    }

    /**
     * The corner the block asks for, run from {@code from}, its other words put in {@code rest};
     * null when it asks for none, {@link Request#FAILED} after an error reported to {@code out}.
     * On the thesis's control (no corners) an R on a sound G01 is {@link Request#refused}: E025
     * reported and the checker's state taken past the block ({@link Lookahead#fixed}, committed by {@link CornerInsertion}), so this
     * is called for such a control only for the block the flow is at.
     */
    Request read(RawBlock b, ModalState from, List<Word> rest, Diagnostics out) {
        Control.Corners form = host.profile().control().corners();
        Word found = null;
        Word second = null;
        List<Word> candidates = new ArrayList<>(2);
        boolean reported = false;
        java.util.List<Word> ws = b.words();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            Word w = ws.get(at);
            if (w.comma()) {
                if (w.letter() == Letter.A || form == Control.Corners.NONE) {
                    reported |= wrongComma(w, out);
                } else if (found == null) {
                    found = w;
                } else if (second == null) {
                    second = w;
                }
                continue;
            }
            Letter l = w.letter();
            // C and R without the comma: Fanuc's 90-degree chamfering and corner R (0i-TF operator's
            // manual, "Chamfering and corner R", CCR = 1); on a Haas the same as ,C and ,R (the
            // classic control's lathe G-code list, "G01 chamfering and corner rounding (X, Z, U, W,
            // B, I, K, R, A, F)", writes them without the comma and Haas school programs use them;
            // the NGC manual writes the comma and names no alarm for the letters alone:
            // docs/chamfer.md, "Without the comma"); a C with the C axis engaged is the axis
            if (l == Letter.C && !host.cAxisOn() || l == Letter.R
                    || form != Control.Corners.NONE && (l == Letter.I || l == Letter.K)) {
                candidates.add(w);
            }
            rest.add(w);
        }
        if (reported) {
            return Request.FAILED;
        }
        if (!candidates.isEmpty() && isG01(b, candidates, from)) {
            rest.removeAll(candidates);
            if (form == Control.Corners.NONE) {
                // the thesis's language has no corner function: R on a G01 is its error 25 (a C
                // is E004, the block's own error). The block is refused, but when it is sound
                // without the R the tool is taken to its end point, as if the R were struck out,
                // so that the blocks after it are not judged from the wrong place (no E101/E049
                // on the next arc)
                Word r = null;
                for (Word w : candidates) {
                    if (w.letter() == Letter.R && r == null) {
                        r = w;
                    } else {
                        rest.add(w);
                    }
                }
                ModalState taken = r != null && candidates.size() == 1
                        ? host.fixed(b.called(rest, b.last(), b.depth())) : null;
                if (taken != null) {
                    out.error(Code.E025_R_NOT_ALLOWED, r.span(), "G01");
                    return Request.refused(taken);
                }
                return null; // the block's own checks report it
            }
            for (Word w : candidates) {
                if (found == null) {
                    found = w;
                } else if (second == null) {
                    second = w;
                }
            }
        }
        if (found == null) {
            return null;
        }
        if (second != null) {
            out.error(Code.E608_TWO_CORNERS, second.span(), found, second);
            return Request.FAILED;
        }
        return new Request(found, found.letter() == Letter.R, size(found, from.units()), square(found, form));
    }

    /**
     * Whether the word asks for a 90-degree corner: I and K on both forms, and Fanuc's C and R
     * without a comma (its "chamfering and corner R"). A comma word is any angle (Haas ,C ,R;
     * Fanuc's direct drawing dimension programming ,C ,R), and so are Haas's C and R written
     * without the comma (docs/chamfer.md, "Without the comma").
     */
    private static boolean square(Word w, Control.Corners form) {
        Letter l = w.letter();
        return !w.comma() && (l == Letter.I || l == Letter.K || form == Control.Corners.LETTERS);
    }

    /**
     * A comma word this control does not read: E604 without corners. (A ,A that reaches here was
     * left by {@link AngleLine}, which reported it.)
     */
    private boolean wrongComma(Word w, Diagnostics out) {
        Control c = host.profile().control();
        if (c.corners() == Control.Corners.NONE) {
            out.error(Code.E604_NO_CORNER_FUNCTION, w.span(), w, c.name());
        }
        return true;
    }

    /** Whether the block without {@code candidates} is a G01 move from {@code from} (dry run, nothing reported). */
    private boolean isG01(RawBlock b, List<Word> candidates, ModalState from) {
        if (host.startsCycle(b)) {
            return false;
        }
        List<Word> without = new ArrayList<>(b.words());
        without.removeAll(candidates);
        Dry dry = host.peek(b.called(without, b.last(), b.depth()), from, new Diagnostics());
        return dry != null && feedLine(dry.block().motions()) != null;
    }

    /** The size in program units, a number without a decimal point read as the control reads X. */
    private double size(Word w, Units u) {
        double v = NumberText.decimal(w.number());
        if (!NumberText.hasPoint(w.number()) && !host.profile().control().noPointLiteral()) {
            v *= u == Units.INCH ? host.profile().noPointInch() : host.profile().noPointMm();
        }
        return Math.abs(v);
    }

    /** A block's one feed move (a G01), or null. */
    static Motion.Linear feedLine(List<Motion> motions) {
        Motion.Linear l = motions.size() == 1 ? gcnc.check.geom.MotionParts.line(motions.get(0)) : null;
        return l != null && !l.rapid() ? l : null;
    }
}
