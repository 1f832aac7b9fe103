package gcnc.check.cycle;

import gcnc.diag.Span;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.List;

/**
 * Writes an expanded cycle's moves as the blocks a programmer would have written by hand, in the
 * cycle block's program coordinates (X a diameter where the machine programs diameters), so that
 * the checker checks them like any other block. Every word stands where the cycle's G word does:
 * a finding in a pass lands on the cycle's line. Numbers always carry a decimal point (the
 * no-point rule never applies) and six decimals, a thousandth of the smallest increment.
 *
 * @param frame the cycle block's program frame
 * @param line  the cycle block's line, every written block's
 * @param at    where the cycle's G word stands, every written word's place
 */
public record MoveWriter(Frame frame, int line, Span at) {
    /**
     * The cycle block's program frame: its work zero (counts), counts per programmed unit of X, of
     * an I (a radius) and of Z, whether X/Z are incremental (G91), and the control's G00-G03 as
     * written ("00", "01", "02", "03").
     */
    public record Frame(Point origin, double perX, double perRadius, double perZ, boolean incremental,
                        List<String> motionCodes) {
        public Frame {
            motionCodes = List.copyOf(motionCodes);
        }
    }

    /** The block of {@code m}, made from {@code from} (where the tool is before it). */
    public RawBlock block(Move m, Point from) {
        List<Word> words = new ArrayList<>(5);
        words.add(new Word(Letter.G, frame.motionCodes().get(m.kind().ordinal()), at));
        Point to = m.to();
        if (frame.incremental()) {
            words.add(word(Letter.X, (to.x() - from.x()) / frame.perX()));
            words.add(word(Letter.Z, (to.z() - from.z()) / frame.perZ()));
        } else {
            words.add(word(Letter.X, (to.x() - frame.origin().x()) / frame.perX()));
            words.add(word(Letter.Z, (to.z() - frame.origin().z()) / frame.perZ()));
        }
        if (m.centre() != null) {
            words.add(word(Letter.I, (m.centre().x() - from.x()) / frame.perRadius()));
            words.add(word(Letter.K, (m.centre().z() - from.z()) / frame.perZ()));
        }
        return new RawBlock(line, words, at, false);
    }

    private Word word(Letter l, double v) {
        return new Word(l, number(v), at);
    }

    /** A value as a word's number: six decimals at most, always a point ("12.5", "0.", "-3.25"). */
    public static String number(double v) {
        BigDecimal d = BigDecimal.valueOf(v).setScale(6, RoundingMode.HALF_EVEN).stripTrailingZeros();
        if (d.signum() == 0) {
            return "0.";
        }
        String s = d.toPlainString();
        return s.contains(".") ? s : s + ".";
    }
}
