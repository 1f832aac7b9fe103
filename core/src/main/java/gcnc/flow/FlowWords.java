package gcnc.flow;

import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.MRole;
import java.util.ArrayList;
import java.util.List;

/**
 * The program-flow words of one block: its call (M98, M97, or the macro call G65) or return (M99)
 * with the P and L that go with it, a macro call's arguments, and the block's other words, which
 * the checker is given. A block has at most one flow word that gcnc follows: the first; a second
 * one stays with the other words (the checker reports it). {@code flow} is null for a block
 * without one. {@code arguments}: a G65's words of the letters that are its arguments (every
 * letter but G, L, N, O and P: Fanuc's argument specification I), in order; null for an M code.
 */
record FlowWords(Word flow, MRole role, Word p, Word l, List<Word> rest, List<Word> arguments) {
    /** Splits a block's words; null for a block without a flow word. */
    static FlowWords of(RawBlock b, FlowCodes codes) {
        Word flow = null;
        List<Word> words = b.words();
        for (int i = 0, n = words.size(); i < n && flow == null; i++) {
            if (codes.flow(words.get(i))) {
                flow = words.get(i);
            }
        }
        if (flow == null) {
            return null;
        }
        MRole role = codes.flowRole(flow);
        List<Word> arguments = codes.macroCall(flow) ? new ArrayList<>() : null;
        Word p = null;
        Word l = null;
        List<Word> rest = new ArrayList<>(b.words().size());
        for (Word w : b.words()) {
            if (w == flow) {
                continue;
            }
            if (w.letter() == Letter.P && p == null) {
                p = w;
            } else if (w.letter() == Letter.L && l == null && role != MRole.RETURN) {
                l = w;
            } else if (arguments != null && argument(w.letter())) {
                arguments.add(w);
            } else {
                rest.add(w);
            }
        }
        return new FlowWords(flow, role, p, l, rest, arguments);
    }

    /** Whether a macro call takes a word of this letter as an argument (not G, L, N, O, P). */
    private static boolean argument(Letter l) {
        return l != Letter.G && l != Letter.L && l != Letter.N && l != Letter.O && l != Letter.P;
    }

    /** The value of a number written with digits only (M98, P1000, L2), or -1 for anything else. */
    static long digits(String number) {
        if (number.isEmpty() || number.length() > 12) {
            return -1;
        }
        long v = 0;
        for (int i = 0; i < number.length(); i++) {
            char c = number.charAt(i);
            if (c < '0' || c > '9') {
                return -1;
            }
            v = v * 10 + (c - '0');
        }
        return v;
    }

    /** The words as the block gives them, for a note ("M98 P1000 L2"). */
    String written() {
        StringBuilder s = new StringBuilder(flow.toString());
        if (p != null) {
            s.append(' ').append(p);
        }
        if (l != null) {
            s.append(' ').append(l);
        }
        return s.toString();
    }
}
