package gcnc.check;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Set;

/**
 * Continuous threads (docs/threading.md, "Continuous threads"): consecutive G32 blocks cut one
 * thread, as the Haas ("synchronization remains in effect for each line in a G32 sequence") and
 * Fanuc controls run them, e.g. the straight thread and its pull-out taper. gcnc holds a G32 pass
 * back until the next block shows whether the thread goes on; the passes of one thread become one
 * {@link Motion.Thread} with a joint where each block ends, carried by the first block (the later
 * ones keep their line, without a move), so the backend gears it once and changes the ratios at
 * each joint without a new synchronisation. Blocks without a move and without M, S or T (an N, an
 * F) may stand between; anything else between ends the thread, and a G32 that continues it then is
 * E627 (not supported yet); a G32 that continues it at another lead is E628.
 */
final class ThreadChain {
    /** Blocks without a move a thread may carry between two of its G32 blocks. */
    static final int STILL_LIMIT = 10;

    private final Diagnostics out;
    /** G32 passes as Threading made them, and those that continue the thread before (nothing moved between). */
    private final Set<CheckedBlock> passes = Collections.newSetFromMap(new IdentityHashMap<>());
    private final Set<CheckedBlock> continuing = Collections.newSetFromMap(new IdentityHashMap<>());
    /** The thread being read: its first pass, then passes and blocks without a move; empty when none. */
    private final List<CheckedBlock> held = new ArrayList<>();
    /** Where in {@link #held} its last pass is. */
    private int lastPass;

    ThreadChain(Diagnostics out) {
        this.out = out;
    }

    /** A G32 pass Threading made; {@code continues}: it starts where the thread before it ended, nothing moved between. */
    void pass(CheckedBlock b, boolean continues) {
        passes.add(b);
        if (continues) {
            continuing.add(b);
        }
    }

    /** Nothing held and nothing marked: blocks go through untouched. */
    boolean idle() {
        return held.isEmpty() && passes.isEmpty();
    }

    /** Takes the next checked blocks, in order; what can be sent on is added to {@code emit}. */
    void accept(List<CheckedBlock> in, List<CheckedBlock> emit) {
        for (CheckedBlock c : in) {
            boolean pass = passes.remove(c);
            boolean continues = continuing.remove(c) && pass;
            if (!held.isEmpty()) {
                if (continues && sameLead(c)) {
                    held.add(c);
                    lastPass = held.size() - 1;
                    continue;
                }
                if (!pass && still(c) && held.size() - lastPass <= STILL_LIMIT) {
                    held.add(c);
                    continue;
                }
                if (continues) {
                    out.error(Code.E628_THREAD_LEAD_CHANGES, Span.of(c.line(), 1), "G32");
                }
                flush(emit);
            } else if (continues) {
                out.error(Code.E627_THREAD_CONTINUED_ACROSS, Span.of(c.line(), 1), "G32", STILL_LIMIT);
            }
            if (pass && thread(c) != null) {
                held.add(c);
                lastPass = 0;
            } else {
                emit.add(c);
            }
        }
        // marks of blocks that did not come through as made (rewritten by the nose compensation): forgotten
        passes.clear();
        continuing.clear();
    }


    /** The program ended: the thread held is sent as it is. */
    void end(List<CheckedBlock> emit) {
        flush(emit);
    }

    /** The one thread pass of a G32 block, or null. */
    private static Motion.Thread thread(CheckedBlock b) {
        Motion.Thread t = b.motions().size() == 1 ? MotionKind.thread(b.motions().get(0)) : null;
        return t != null && !t.chamfered() && t.joints().isEmpty() ? t : null;
    }

    private boolean sameLead(CheckedBlock c) {
        Motion.Thread t = thread(c);
        Motion.Thread first = thread(held.get(0));
        return t != null && Math.abs(t.lead() - first.lead()) <= 1e-9 * first.lead() && t.reverse() == first.reverse();
    }

    /** A block the thread can run through: no move, no dwell, no M, no speed or tool change. */
    private static boolean still(CheckedBlock c) {
        return c.motions().isEmpty() && c.before().isEmpty() && c.after().isEmpty() && c.spindleRpm().isEmpty()
                && c.tool().isEmpty();
    }

    /** Sends the thread held: its passes as one geared motion on the first, the other blocks without a move. */
    private void flush(List<CheckedBlock> emit) {
        if (held.isEmpty()) {
            return;
        }
        CheckedBlock first = held.get(0);
        Motion.Thread t0 = thread(first);
        Motion.Thread last = thread(held.get(lastPass));
        List<Point> joints = new ArrayList<>();
        for (int i = 0; i < lastPass; i++) {
            Motion.Thread t = thread(held.get(i));
            if (t != null) {
                joints.add(t.to());
            }
        }
        if (joints.isEmpty()) {
            emit.add(first);
        } else {
            Motion.Thread whole = new Motion.Thread(t0.from(), last.to(), t0.lead(), t0.rpm(), t0.reverse(), t0.feed(),
                    null, joints);
            emit.add(first.withMotions(List.of(whole), last.to()));
        }
        for (int i = 1; i < held.size(); i++) {
            CheckedBlock b = held.get(i);
            emit.add(thread(b) == null || i > lastPass ? b : b.withMotions(List.of(), b.end()));
        }
        held.clear();
    }
}
