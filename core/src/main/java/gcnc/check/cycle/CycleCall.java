package gcnc.check.cycle;

import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntFunction;

/**
 * The words of a G70, G71 or G72 block, read and checked against the cycle's forms:
 * <ul>
 * <li>Fanuc two-block form, first block: {@code G71 U(depth) R(retract)}, {@code G72 W(depth)
 *     R(retract)}; second block {@code G71 P Q U(X allowance, diameter) W(Z allowance) F S};</li>
 * <li>Haas one-block form: {@code G71 P Q U W D(depth) F}, {@code R1} for type II (the Haas YASNAC
 *     form; the rough allowances I and K are E164);</li>
 * <li>G73 pattern repeat: Fanuc {@code G73 U(X relief, radius) W(Z relief) R(passes)} then
 *     {@code G73 P Q U W F}; Haas {@code G73 P Q U W I(X relief) K(Z relief) D(passes) F};</li>
 * <li>{@code G70 P Q} (F and S allowed, as Haas programs write them; U, W and D are ignored by the
 *     control, warning E642).</li>
 * </ul>
 * Words of other functions (N, F, S, T, M, G codes of other groups) are handed on to a block of
 * their own before the cycle's moves ({@link #passOn}). U, W, D and R follow the no-point rule.
 *
 * @param kind    G70, G71 or G72 by function
 * @param g       the cycle's G word (where its findings go)
 * @param words   the cycle's own words by letter
 * @param values  their values (coordinates after the no-point rule, P/Q as integers)
 * @param passOn  the words for the block before the moves
 */
public record CycleCall(GRole kind, Word g, Map<Letter, Word> words, Map<Letter, Double> values, List<Word> passOn) {
    public CycleCall {
        words = Map.copyOf(words);
        values = Map.copyOf(values);
        passOn = List.copyOf(passOn);
    }

    /** The Fanuc first block: depth and retract only, no contour. */
    public boolean firstOfTwo() {
        return kind != GRole.FINISHING_CYCLE && !words.containsKey(Letter.P) && !words.containsKey(Letter.Q);
    }

    public boolean has(Letter l) {
        return words.containsKey(l);
    }

    public double value(Letter l) {
        return values.get(l);
    }

    public long label(Letter l) {
        return values.get(l).longValue();
    }

    /** Haas {@code R1} on a G71/G72 with its contour: type II roughing whatever the contour's first block. */
    public boolean typeTwo() {
        return !firstOfTwo() && has(Letter.R) && NumberText.decimal(words.get(Letter.R).number()) == 1;
    }

    /** The cycle's name as written ("G71"). */
    public String name() {
        return "G" + g.number();
    }

    /**
     * Reads the cycle block whose cycle word is {@code g}; null after reporting the block's first
     * error. {@code cycleOf} tells which G numbers are cycles (another cycle in the block is
     * E161); {@code noPoint} scales a U/W/D/R written without a decimal point.
     */
    public static CycleCall read(RawBlock b, Word g, GRole kind, IntFunction<GRole> roleOf, double noPoint,
                                 Diagnostics out) {
        Map<Letter, Word> words = new EnumMap<>(Letter.class);
        Map<Letter, Double> values = new EnumMap<>(Letter.class);
        List<Word> passOn = new ArrayList<>();
        String name = "G" + g.number();
        for (Word w : b.words()) {
            if (w == g) {
                continue;
            }
            switch (w.letter()) {
                case N, F, S, T, M -> passOn.add(w);
                case G -> {
                    GRole r = roleOf.apply((int) w.code());
                    if (r != null && r.contourCycle()) {
                        out.error(Code.E161_CYCLE_WORD, w.span(), name, w);
                        return null;
                    }
                    passOn.add(w);
                }
                case P, Q, U, W, D, R, I, K -> {
                    if (words.containsKey(w.letter())) {
                        out.error(Code.E007_DUPLICATE_PARAMETER, w.span(), w.letter());
                        return null;
                    }
                    Double v = value(w, noPoint, out);
                    if (v == null) {
                        return null;
                    }
                    words.put(w.letter(), w);
                    values.put(w.letter(), v);
                }
                default -> {
                    out.error(Code.E161_CYCLE_WORD, w.span(), name, w);
                    return null;
                }
            }
        }
        CycleCall call = new CycleCall(kind, g, words, values, passOn);
        return call.fits(out) ? call : null;
    }

    /**
     * Only the P and Q of a cycle block that {@link #read} rejected, when both are whole numbers:
     * the contour the cycle names is still skipped by the control and kept for its G70. Null otherwise.
     */
    public static CycleCall labels(RawBlock b, Word g, GRole kind) {
        Map<Letter, Word> words = new EnumMap<>(Letter.class);
        Map<Letter, Double> values = new EnumMap<>(Letter.class);
        for (Word w : b.words()) {
            if ((w.letter() == Letter.P || w.letter() == Letter.Q) && !words.containsKey(w.letter())) {
                long n = w.code();
                if (n == NumberText.NOT_INTEGER) {
                    return null;
                }
                words.put(w.letter(), w);
                values.put(w.letter(), (double) n);
            }
        }
        return words.size() == 2 ? new CycleCall(kind, g, words, values, List.of()) : null;
    }

    private static Double value(Word w, double noPoint, Diagnostics out) {
        if (w.letter() == Letter.P || w.letter() == Letter.Q) {
            long n = w.code();
            if (n == NumberText.NOT_INTEGER) {
                out.error(Code.E013_INTEGER_EXPECTED, w.span(), w.letter());
                return null;
            }
            return (double) n;
        }
        double v = NumberText.decimal(w.number());
        if (Double.isNaN(v)) {
            out.error(Code.E014_DECIMAL_EXPECTED, w.span(), w.letter());
            return null;
        }
        return NumberText.hasPoint(w.number()) ? v : v * noPoint;
    }

    /** The words this form of this cycle takes; E161, E164 or E168 at the first that does not fit. */
    private boolean fits(Diagnostics out) {
        if (has(Letter.P) != has(Letter.Q) || kind == GRole.FINISHING_CYCLE && !has(Letter.P)) {
            out.error(Code.E168_CYCLE_P_Q_MISSING, g.span(), name());
            return false;
        }
        Letter depth = kind == GRole.FACING_CYCLE ? Letter.W : Letter.U;
        boolean pattern = kind == GRole.PATTERN_CYCLE;
        for (Word w : words.values().stream().sorted(java.util.Comparator.comparing(Word::span)).toList()) {
            Letter l = w.letter();
            boolean ok;
            if (kind == GRole.FINISHING_CYCLE) {
                ok = l == Letter.P || l == Letter.Q;
                if (l == Letter.U || l == Letter.W || l == Letter.D) {
                    // a G70 takes P and Q only, but the control runs one that carries the roughing's
                    // allowances or depth (CAM output and shop habit): they do nothing (E642)
                    out.report(Diagnostic.warning(Code.E642_FINISH_WORD_IGNORED, w.span(), name(), w));
                    continue;
                }
            } else if (firstOfTwo()) {
                ok = l == depth || l == Letter.R || pattern && (l == Letter.U || l == Letter.W);
            } else if (pattern) {
                ok = l != Letter.R;
            } else if (l == Letter.I || l == Letter.K) {
                out.error(Code.E164_CYCLE_OPTION_NOT_SUPPORTED, w.span(), name(), w);
                return false;
            } else {
                ok = l != Letter.R || NumberText.decimal(w.number()) == 1;
            }
            if (!ok) {
                out.error(Code.E161_CYCLE_WORD, w.span(), name(), w);
                return false;
            }
        }
        return true;
    }
}
