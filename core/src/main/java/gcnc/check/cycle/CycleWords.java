package gcnc.check.cycle;

import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;

/**
 * The words of a peck or drilling cycle block (G74, G75, G81-G83), sorted out: the end point's
 * axis words (X U Z W, resolved later like a move's), the cycle's own words with their values,
 * and the words of other functions (N F S T M, G codes of other groups) handed on to a block of
 * their own before the moves. Values: a letter in {@code increments} is a whole number of least
 * increments (Fanuc's P and Q of G74/G75: no decimal point, E013); any other follows the control's
 * no-point rule (scaled by {@code noPoint} when written without a point).
 *
 * @param axes   the X U Z W words, in order
 * @param words  the cycle's own words by letter
 * @param values their values in program units
 * @param passOn the words for the block before the moves
 */
public record CycleWords(List<Word> axes, Map<Letter, Word> words, Map<Letter, Double> values, List<Word> passOn) {
    public CycleWords {
        axes = List.copyOf(axes);
        words = Map.copyOf(words);
        values = Map.copyOf(values);
        passOn = List.copyOf(passOn);
    }

    public boolean has(Letter l) {
        return words.containsKey(l);
    }

    public double value(Letter l) {
        return values.get(l);
    }

    public Word word(Letter l) {
        return words.get(l);
    }

    /** Whether an axis word along X (X or U) or along Z (Z or W) is given. */
    public boolean hasAxis(boolean alongX) {
        return axes.stream().anyMatch(w -> alongX ? w.letter() == Letter.X || w.letter() == Letter.U
                : w.letter() == Letter.Z || w.letter() == Letter.W);
    }

    /**
     * Reads the block whose cycle word is {@code g} (null: a block that makes a modal cycle again),
     * {@code name} the cycle's name for the findings; null after reporting its first error.
     * {@code own}: the letters the cycle takes; {@code increment} the least increment in program
     * units; {@code isCycle} which G words are cycles (another cycle in the block is E161).
     */
    public static CycleWords read(RawBlock b, Word g, String name, Set<Letter> own, Set<Letter> increments, double noPoint,
                                  double increment, Predicate<Word> isCycle, Diagnostics out) {
        List<Word> axes = new ArrayList<>();
        Map<Letter, Word> words = new EnumMap<>(Letter.class);
        Map<Letter, Double> values = new EnumMap<>(Letter.class);
        List<Word> passOn = new ArrayList<>();
        for (Word w : b.words()) {
            if (w == g) {
                continue;
            }
            Letter l = w.letter();
            switch (l) {
                case X, U, Z, W -> axes.add(w);
                case N, F, S, T, M -> passOn.add(w);
                case G -> {
                    if (isCycle.test(w)) {
                        out.error(Code.E161_CYCLE_WORD, w.span(), name, w);
                        return null;
                    }
                    passOn.add(w);
                }
                default -> {
                    if (!own.contains(l)) {
                        out.error(Code.E161_CYCLE_WORD, w.span(), name, w);
                        return null;
                    }
                    if (words.containsKey(l)) {
                        out.error(Code.E007_DUPLICATE_PARAMETER, w.span(), l);
                        return null;
                    }
                    Double v = increments.contains(l) ? increments(w, increment, out) : decimal(w, noPoint, out);
                    if (v == null) {
                        return null;
                    }
                    words.put(l, w);
                    values.put(l, v);
                }
            }
        }
        return new CycleWords(axes, words, values, passOn);
    }

    private static Double increments(Word w, double increment, Diagnostics out) {
        long n = w.code();
        if (n == Word.NOT_INTEGER || NumberText.hasPoint(w.number())) {
            out.error(Code.E013_INTEGER_EXPECTED, w.span(), w.letter());
            return null;
        }
        return n * increment;
    }

    private static Double decimal(Word w, double noPoint, Diagnostics out) {
        double v = NumberText.decimal(w.number());
        if (Double.isNaN(v)) {
            out.error(Code.E014_DECIMAL_EXPECTED, w.span(), w.letter());
            return null;
        }
        return NumberText.hasPoint(w.number()) ? v : v * noPoint;
    }
}
