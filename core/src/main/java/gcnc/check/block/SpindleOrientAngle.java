package gcnc.check.block;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;

/**
 * The angle of a spindle orientation, Haas {@code M19 P90} (whole degrees) or {@code M19 R90.5}
 * (degrees with decimals), Haas lathe manual M19: the block's P or R belongs to the M19, not to a
 * G function or the modal motion. gcnc follows M19 as its output says (the shipped profiles give it
 * none: E113), so the angle is checked, 0 to 360, and goes nowhere else. Emits E703.
 */
final class SpindleOrientAngle {
    private SpindleOrientAngle() {
    }

    /**
     * Whether the block is an M19 with its angle and nothing for a G function (no G, no axis word
     * other than R): then P/R are the angle, checked here (E703), and the block has no owner function.
     */
    static boolean owns(BlockDraft d, Diagnostics out) {
        if (!d.has(Letter.P) && !d.has(Letter.R)) {
            return false;
        }
        boolean orient = false;
        java.util.List<Word> ws = d.block.words();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            Word w = ws.get(at);
            switch (w.letter()) {
                case G, X, Z, U, W, I, K -> {
                    return false;
                }
                case M -> {
                    MFunction f = w.number().isEmpty() ? null : d.functions.m(w.code());
                    orient |= f != null && f.role() == MRole.SPINDLE_ORIENT;
                }
                default -> { }
            }
        }
        if (!orient) {
            return false;
        }
        for (Letter l : new Letter[] {Letter.P, Letter.R}) {
            if (d.has(l)) {
                Word w = d.word(l);
                double v = degrees(w.number(), l == Letter.P);
                if (!(v >= 0 && v <= 360)) {
                    d.fail(out, Code.E703_ORIENT_ANGLE, w.span(), w);
                    return true;
                }
            }
        }
        return true;
    }

    /** P: whole degrees, with or without a point ({@code P90}, {@code P90.}); R: any decimal. NaN otherwise. */
    private static double degrees(String number, boolean whole) {
        try {
            double v = Double.parseDouble(number);
            return whole && v != Math.rint(v) ? Double.NaN : v;
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }
}
