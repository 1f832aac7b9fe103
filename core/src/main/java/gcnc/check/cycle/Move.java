package gcnc.check.cycle;

import gcnc.ir.Point;

/**
 * One move of an expanded cycle, machine counts, before it is written as a block: where it goes,
 * how (rapid, feed, or an arc about {@code centre}), and which pass of the cycle it belongs to.
 */
public record Move(Kind kind, Point to, Point centre, int pass) {
    /** How the tool goes there: G00, G01, G02 or G03. */
    public enum Kind { RAPID, FEED, ARC_CW, ARC_CCW }

    public static Move line(boolean rapid, Point to, int pass) {
        return new Move(rapid ? Kind.RAPID : Kind.FEED, to, null, pass);
    }
}
