package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * What a call's words ask for: the program number an M98's P names or the label an M97's P
 * names, and how many times it runs (L, or on Fanuc the digits of P before the program number).
 * Made only from words that make a call: otherwise the reason is reported (E132 no P, E130 no
 * program number, E013 no label, E135 a bad count, E143 two counts) and there is no target.
 */
record CallTarget(long number, int repeats) {
    /** The largest repeat count (L, or the leading digits of a Fanuc P): four digits. */
    private static final int MAX_REPEAT = 9999;

    /**
     * The program an M98 calls and how often, or null after reporting why it does not run;
     * {@code countInP}: the control reads a P of more than four digits as count and number.
     */
    static CallTarget program(FlowWords w, boolean countInP, Diagnostics diags) {
        if (withoutP(w, diags)) {
            return null;
        }
        long p = FlowWords.digits(w.p().number());
        if (p < 0) {
            diags.error(Code.E130_NO_PROGRAM_HERE, w.p().span(), w.p().number());
            return null;
        }
        long number = p;
        long repeats = 1;
        boolean inP = countInP && w.p().number().length() > 4;
        if (inP) {
            number = p % 10_000;
            repeats = p / 10_000 == 0 ? 1 : p / 10_000;
            if (repeats > MAX_REPEAT) {
                diags.error(Code.E135_BAD_REPEAT_COUNT, w.p().span(), w.p());
                return null;
            }
        }
        if (w.l() != null) {
            if (inP && p / 10_000 > 0) {
                diags.error(Code.E143_TWO_REPEAT_COUNTS, w.l().span(), w.written());
                return null;
            }
            repeats = repeats(w.l(), diags);
            if (repeats < 0) {
                return null;
            }
        }
        return new CallTarget(number, (int) repeats);
    }

    /** The label a Haas M97 P n calls (n) and how often, or null after reporting why it does not run. */
    static CallTarget label(FlowWords w, Diagnostics diags) {
        if (withoutP(w, diags)) {
            return null;
        }
        long label = FlowWords.digits(w.p().number());
        long repeats = w.l() == null ? 1 : repeats(w.l(), diags);
        if (repeats < 0) {
            return null;
        }
        if (label < 0) {
            diags.error(Code.E013_INTEGER_EXPECTED, w.p().span(), "P");
            return null;
        }
        return new CallTarget(label, (int) repeats);
    }

    /** Whether a call has no P (E132 at it, and it does not run). */
    private static boolean withoutP(FlowWords w, Diagnostics diags) {
        if (w.p() == null) {
            diags.error(Code.E132_CALL_WITHOUT_P, w.flow().span(), w.flow());
            return true;
        }
        return false;
    }

    /** The repeat count an L word gives (1-9999), or -1 after E135. */
    private static long repeats(Word l, Diagnostics diags) {
        long repeats = FlowWords.digits(l.number());
        if (repeats < 1 || repeats > MAX_REPEAT) {
            diags.error(Code.E135_BAD_REPEAT_COUNT, l.span(), l);
            return -1;
        }
        return repeats;
    }
}
