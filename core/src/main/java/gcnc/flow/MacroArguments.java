package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.machine.Units;
import java.util.EnumMap;
import java.util.Map;

/**
 * A macro call's arguments ({@code G65 P9010 A1. X24.}): the local variables of the called
 * program's new level. Each address gives the variable of Fanuc's argument specification I (Fanuc
 * 0i-F custom macro, "Argument specification"; the Haas macro manual's G65 table is the same); the
 * other locals of the level are vacant.
 *
 * <p>A value with a decimal point is that value. Without one the control reads it in the least
 * input increment of its address, as the block's own words: {@code X24} under G21 is 0.024 (mm), under
 * G20 0.0024 (in), by the profile's {@code input.no_point}; M, S and T, whose addresses take whole
 * numbers, as written. The manuals' own advice is a decimal point in every argument. A value
 * worked out from a variable ({@code A#1}) has its point already (gcnc.flow.MacroLine).
 *
 * <p>Not followed yet, each E110 at its word: an address given twice (argument specification II,
 * which repeats I, J and K for #4-#33), and L above 1 (the call repeated).
 */
final class MacroArguments {
    /** Argument specification I: the local variable of each address. */
    private static final Map<Letter, Integer> VARIABLE = new EnumMap<>(Letter.class);

    static {
        String[] spec = {"A1", "B2", "C3", "I4", "J5", "K6", "D7", "E8", "F9", "H11", "M13", "Q17", "R18", "S19",
                "T20", "U21", "V22", "W23", "X24", "Y25", "Z26"};
        for (String s : spec) {
            VARIABLE.put(Letter.of(s.charAt(0)), Integer.parseInt(s.substring(1)));
        }
    }

    private MacroArguments() {
    }

    /**
     * The new level's locals (#1-#33 at [1]..[33], null vacant) that a macro call's words give, or
     * null after reporting why the call is not followed.
     *
     * @param units   the input units in force at the call (G20/G21)
     * @param noPoint the value of a whole number written without a decimal point in those units
     */
    static Double[] read(FlowWords w, Units units, double noPoint, Diagnostics diags) {
        if (w.l() != null && FlowWords.digits(w.l().number()) != 1) {
            diags.error(Code.E110_NOT_SUPPORTED_YET, w.l().span(), w.written(), "a macro call repeated by L");
            return null;
        }
        Double[] level = new Double[Variables.LOCALS];
        Map<Letter, Word> given = new EnumMap<>(Letter.class);
        for (Word a : w.arguments()) {
            Word first = given.putIfAbsent(a.letter(), a);
            if (first != null) {
                diags.error(Code.E110_NOT_SUPPORTED_YET, a.span(), first + " " + a,
                        "in one macro call (argument specification II, or an address given twice)");
                return null;
            }
            double v = Word.decimal(a.number());
            if (Double.isNaN(v)) {
                diags.error(Code.E014_DECIMAL_EXPECTED, a.span(), a.letter());
                return null;
            }
            if (a.number().indexOf('.') < 0 && !whole(a.letter())) {
                v *= noPoint;
            }
            level[VARIABLE.get(a.letter())] = v;
        }
        return level;
    }

    /** M, S and T take whole numbers: a value without a point is read as written. */
    private static boolean whole(Letter l) {
        return l == Letter.M || l == Letter.S || l == Letter.T;
    }
}
