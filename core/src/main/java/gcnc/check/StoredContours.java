package gcnc.check;

import gcnc.check.cycle.Axes;
import gcnc.check.cycle.CycleCall;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The contours G71/G72/G73 read, kept for a later G70 under their P/Q labels (the oldest is
 * forgotten first, past {@link #STORED}), and the G70's search for the blocks it finishes: the
 * stored contour its P and Q name, part of one, or one that starts among the blocks a cycle passed
 * over (docs/cycles.md).
 */
final class StoredContours {
    /** How many contours are kept for a later G70 (the oldest is forgotten first). */
    static final int STORED = 100;

    private final Map<String, Stored> stored = new LinkedHashMap<>(16, 0.75f, false) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Stored> eldest) {
            return size() > STORED;
        }
    };

    /**
     * A contour kept for G70: its blocks and how the cycle that read it cut; {@code axes} null when
     * the cycle or its contour had an error (a G70 over it then does nothing rather than repeat it).
     * {@code passedOver}: the blocks between the cycle and N(P), which the cycle never ran but a G70
     * whose P names one of them does (the control searches the program for N(P)).
     */
    record Stored(List<RawBlock> blocks, List<RawBlock> passedOver, Axes axes, int depthSign, String name,
                          int line) {
        boolean usable() {
            return axes != null;
        }
    }

    /** What a G70 finishes: the stored contour it found and its blocks N(P)..N(Q). */
    record Found(Stored contour, List<RawBlock> blocks) {
    }

    /** Forgets the contour the call's P and Q name (a new cycle with the same labels reads its own). */
    void forget(CycleCall call) {
        stored.remove(key(call));
    }

    /** Keeps {@code s} under the call's P and Q. */
    void keep(CycleCall call, Stored s) {
        stored.put(key(call), s);
    }

    /**
     * G70: the stored contour its P and Q name; else part of one (E643: the control finishes the
     * blocks N(P)..N(Q) wherever they stand); else one that starts in the blocks a cycle passed over
     * before its contour; else E166 (the control's alarm: no such blocks) and null. Findings to {@code out}.
     */
    Found find(CycleCall call, Diagnostics out) {
        Stored s = stored.get(key(call));
        List<RawBlock> blocks = s == null ? null : s.blocks();
        if (s == null) {
            for (Stored whole : stored.values()) {
                blocks = part(whole.blocks(), call.label(Letter.P), call.label(Letter.Q));
                if (blocks != null) {
                    s = whole;
                    out.report(gcnc.diag.Diagnostic.warning(Code.E643_FINISH_PART_OF_CONTOUR, call.g().span(),
                            call.name(), call.label(Letter.P), call.label(Letter.Q), sequence(whole.blocks().get(0)),
                            sequence(whole.blocks().get(whole.blocks().size() - 1)), whole.name(), whole.line()));
                    break;
                }
            }
        }
        if (s == null) {
            // N(P) among the blocks a cycle passed over before its contour (a G42 block numbered
            // as the finish's start: N5 G42 G00 X20. before N10): the control finds it and runs
            // N(P)..N(Q) through the contour (issue 31)
            for (Stored whole : stored.values()) {
                if (whole.passedOver().isEmpty()) {
                    continue;
                }
                List<RawBlock> all = new ArrayList<>(whole.passedOver());
                all.addAll(whole.blocks());
                blocks = part(all, call.label(Letter.P), call.label(Letter.Q));
                if (blocks != null) {
                    s = whole;
                    break;
                }
            }
        }
        if (s == null) {
            out.error(Code.E166_FINISH_WITHOUT_CONTOUR, call.g().span(), call.name(), call.label(Letter.P),
                    call.label(Letter.Q));
            return null;
        }
        return new Found(s, blocks);
    }

    /** The blocks N(first)..N(last) of a contour, in order, or null when it has not both. */
    private static List<RawBlock> part(List<RawBlock> blocks, long first, long last) {
        int from = -1;
        for (int i = 0; i < blocks.size(); i++) {
            long n = sequence(blocks.get(i));
            if (from < 0 && n == first) {
                from = i;
            }
            if (from >= 0 && n == last) {
                return blocks.subList(from, i + 1);
            }
        }
        return null;
    }

    /** The block's N number, or -1 without one. */
    static long sequence(RawBlock b) {
        Word n = nWord(b);
        return n == null ? -1 : n.code();
    }

    /** The block's N word, or null. */
    static Word nWord(RawBlock b) {
        for (Word w : b.words()) {
            if (w.letter() == Letter.N) {
                return w;
            }
        }
        return null;
    }

    private static String key(CycleCall call) {
        return call.label(Letter.P) + "/" + call.label(Letter.Q);
    }
}
