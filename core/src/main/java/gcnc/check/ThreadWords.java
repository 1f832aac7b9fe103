package gcnc.check;

import gcnc.check.geom.NumberText;

/**
 * Small rules of the thread cycles' words kept apart from {@link Threading} (docs/threading.md):
 * the Haas G76 tool angle A as the posts write it, and the Z offsets of the Haas infeed with both
 * flanks in turn (P2, P4).
 */
final class ThreadWords {
    private ThreadWords() {
    }

    /**
     * The whole degrees of a Haas G76 A word, or {@link NumberText#NOT_INTEGER}: {@code A60} and
     * {@code A60.} are both 60 degrees. The Haas manual writes A without a point; the Fusion Haas
     * post writes {@code A60.} and the control runs it, so a point with nothing after it (or
     * zeros) is accepted; a fraction ({@code A59.5}) is not a tool angle the control takes.
     */
    static long degrees(String number) {
        if (!NumberText.hasPoint(number)) {
            return NumberText.integer(number);
        }
        try {
            double v = Double.parseDouble(number);
            return v == Math.rint(v) && v >= 0 ? (long) v : NumberText.NOT_INTEGER;
        } catch (NumberFormatException e) {
            return NumberText.NOT_INTEGER;
        }
    }

    /**
     * The degrees of a start angle Q (G92 and the Haas one-block G76; Fanuc G92 "Q: shift angle of
     * the threading start", Haas "Q: thread start angle, do not use a decimal point"): a whole number
     * of thousandths of a degree, 0 to 360000 (360000 is a whole turn: 0); NaN for anything else.
     */
    static double startAngle(String number) {
        long v = NumberText.hasPoint(number) ? NumberText.NOT_INTEGER : NumberText.integer(number);
        if (v == NumberText.NOT_INTEGER || v < 0 || v > 360000) {
            return Double.NaN;
        }
        return v % 360000 / 1000.0;
    }

    /**
     * How far back along Z (away from the cut's direction, program units, radius depths as the
     * cycle's) pass {@code index} (0 first) of a Haas G76 P2/P4 starts and ends: both flanks in
     * turn. The finished form is the one-flank infeed's (its apex {@code height · tan(angle / 2)}
     * back, one flank through the programmed end at the top), so no pass goes past the programmed
     * Z; even passes put the tool's flank on that form's front flank (back by {@code depth · tan}, as
     * P1/P3 do every pass), odd ones on its back flank (back by {@code (2 · height − depth) · tan});
     * at the full height both are the apex.
     */
    static double alternate(int index, double height, double depth, double flankTan) {
        return (index % 2 == 0 ? depth : 2 * height - depth) * flankTan;
    }
}
