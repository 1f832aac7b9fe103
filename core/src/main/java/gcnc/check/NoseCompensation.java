package gcnc.check;

import static gcnc.check.NoseMoves.after;
import static gcnc.check.NoseMoves.before;
import static gcnc.check.NoseMoves.from;
import static gcnc.check.NoseMoves.line;
import static gcnc.check.NoseMoves.path;
import static gcnc.check.NoseMoves.startingAt;
import static gcnc.check.NoseMoves.still;
import static gcnc.check.NoseMoves.to;
import static gcnc.check.NoseMoves.with;

import gcnc.check.geom.NoseGeometry;
import gcnc.check.geom.NoseGeometry.Corner;
import gcnc.check.geom.NoseGeometry.Element;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import gcnc.machine.Nose;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;

/**
 * Tool nose radius compensation (G41/G42/G40) over the checked blocks, in the order they reach the
 * machine (docs/nose-compensation.md). The checker keeps the programmed contour as the program's
 * position; this stage rewrites the motions of the blocks under G41/G42 so that the imaginary tool
 * tip moves where the control moves it: the nose centre on the contour offset by the nose radius,
 * corners as a Fanuc type C control makes them, start-up and cancel of type A, the tip shifted
 * from the centre by the tip direction. A block keeps its line; corner moves belong to the block
 * they end.
 *
 * <p>To place a corner it must see the next move: the block before it is held back until then,
 * with at most {@value #STILL_LIMIT} blocks without a move between (E176 past that). Blocks the
 * control runs under G41/G42 without offsetting them (G28, a T word, a cycle other than G70, a side
 * change: {@link NoseSuspend}) end the compensated path and start it again after them. Errors:
 * E170 (start-up shorter than the radius), E171 (an arc starts or cancels), E172 (a concave corner
 * the nose does not fit), E173 (a concave arc tighter than the nose), E175 (the program ends under
 * G41/G42, a warning), E177 (a note: the offset has no nose radius, nothing is moved), E179 (a
 * compensated move beyond the travel).
 */
final class NoseCompensation {
    /** Blocks without a move gcnc holds while it looks for the next corner. */
    static final int STILL_LIMIT = 10;

    private enum Mode { OFF, ARMED, ACTIVE }

    private final MachineProfile profile;
    private final Diagnostics out;
    private final BitSet noted = new BitSet();
    private Mode mode = Mode.OFF;
    /** The signed offset: + nose radius for G42, - for G41 (counts). */
    private double e;
    private double[] tip = {0, 0};
    /** The block whose end waits for the next move, and its element (null: the start-up block). */
    private CheckedBlock pending;
    private NoseInfo pendingInfo;
    private Element pendingElement;
    /** Where the pending element's offset starts (nose centre); for the start-up block, unused. */
    private Point pendingStart;
    private final List<CheckedBlock> held = new ArrayList<>();
    /** A G40 without a move was met: the next move is the cancel move. */
    private boolean exiting;
    /**
     * Where the tool stands when it is off the programmed point with no compensated element to
     * follow: after E176, or after a suspension by a block without a move (a T word, G41 under
     * G42); the next move starts from there.
     */
    private Point restartFrom;
    /** After E176: the rapid from there to the start of the pending element's offset, sent before it. */
    private Motion lead;

    NoseCompensation(MachineProfile profile, Diagnostics out) {
        this.profile = profile;
        this.out = out;
    }

    /** The same compensation in progress, reporting to {@code to}: for the other position of the block delete switch. */
    NoseCompensation copy(Diagnostics to) {
        NoseCompensation c = new NoseCompensation(profile, to);
        c.noted.or(noted);
        c.mode = mode;
        c.e = e;
        c.tip = tip.clone();
        c.pending = pending;
        c.pendingInfo = pendingInfo;
        c.pendingElement = pendingElement;
        c.pendingStart = pendingStart;
        c.held.addAll(held);
        c.exiting = exiting;
        c.restartFrom = restartFrom;
        c.lead = lead;
        return c;
    }

    /** Whether compensation is in force here (blocks may be held). */
    boolean active() {
        return mode != Mode.OFF;
    }

    /** Takes the next checked block; what can be sent on is added to {@code emit}, in order. */
    void accept(CheckedBlock b, NoseInfo info, List<CheckedBlock> emit) {
        if (info.suspend() != NoseSuspend.NONE && info.side() != NoseSide.OFF && mode != Mode.OFF && !exiting) {
            suspend(b, info, emit);
            return;
        }
        if (mode == Mode.OFF) {
            if (info.side() == NoseSide.OFF) {
                emit.add(resumed(b));
                return;
            }
            arm(info);
        }
        if (mode == Mode.ARMED) {
            armed(b, info, emit);
            return;
        }
        List<Motion> path = path(b);
        if (path.isEmpty()) {
            if (info.side() == NoseSide.OFF) {
                exiting = true;
            }
            held.add(b.motions().isEmpty() ? b : with(b, still(b), b.end()));
            if (held.size() > STILL_LIMIT) {
                out.report(info.error(Code.E176_NOSE_TOO_MANY_STILL_BLOCKS, STILL_LIMIT));
                Point end = closePerpendicular(emit);
                flushHeld(emit);
                if (end != null) {
                    restartFrom = tipAt(end);
                }
            }
            return;
        }
        if (info.side() == NoseSide.OFF || exiting) {
            cancel(b, info, path, emit);
            return;
        }
        Element next = Element.of(path.get(0));
        if (pending == null) {
            // after E176: a new start from where the tool stands
            Point start = next.offsetAt(next.from(), e);
            lead = new Motion.Linear(true, restartFrom, tipAt(start), null);
            restartFrom = null;
            pending = b;
            pendingInfo = info;
            pendingElement = next;
            pendingStart = start;
            flushHeld(emit);
            return;
        }
        follow(b, info, next, emit);
    }

    /** The program ended (M30) or the input did: sends what is held, with the warning E175. */
    void end(Span at, List<CheckedBlock> emit) {
        if (mode == Mode.OFF) {
            return;
        }
        out.report(Diagnostic.warning(Code.E175_NOSE_AT_END, at, e < 0 ? "G41" : "G42"));
        if (pending != null) {
            closePerpendicular(emit);
        }
        flushHeld(emit);
        mode = Mode.OFF;
        exiting = false;
    }

    private void arm(NoseInfo info) {
        Nose n = info.nose();
        double sign = info.side() == NoseSide.RIGHT ? 1 : -1;
        e = sign * n.radius();
        double[] v = n.tipVector();
        tip = new double[] {v[0] * n.radius(), v[1] * n.radius()};
        mode = Mode.ARMED;
        exiting = false;
        if (n.radius() == 0 && !noted.get(info.offset())) {
            noted.set(info.offset());
            out.report(new Diagnostic(Code.E177_NOSE_NO_RADIUS, gcnc.diag.Severity.NOTE, info.at(),
                    List.of(info.side().g(), Integer.toString(info.offset()), profile.name()), info.origin()));
        }
    }

    /** G41/G42 given, no move yet: the first move is the start-up. */
    private void armed(CheckedBlock b, NoseInfo info, List<CheckedBlock> emit) {
        List<Motion> path = path(b);
        if (info.side() == NoseSide.OFF) {
            mode = Mode.OFF;
            emit.add(resumed(b));
            return;
        }
        if (path.isEmpty() || info.suspend() == NoseSuspend.CYCLE || MotionKind.of(path.get(0)) == MotionKind.THREAD) {
            // a cycle's block or a thread is not offset (E624): the next move is the start-up. (Reached here
            // when the block that gave G41/G42 had an error, so that this block arms the compensation.)
            emit.add(b);
            return;
        }
        Motion first = path.get(0);
        if (!arcAtEnd(first, info) && e != 0 && Element.of(first).length() < Math.abs(e)) {
            out.report(info.error(Code.E170_NOSE_START_UP_TOO_SHORT, info.side().g(),
                    mm(Element.of(first).length()), mm(Math.abs(e))));
        }
        mode = Mode.ACTIVE;
        pending = b;
        pendingInfo = info;
        pendingElement = null;
        pendingStart = null;
    }

    /** A move under G41/G42 after another: the corner between them ends the held block. */
    private void follow(CheckedBlock b, NoseInfo info, Element next, List<CheckedBlock> emit) {
        Point startNext;
        if (pendingElement == null) {
            // the start-up block (type A): the nose goes to the next element's offset start
            startNext = next.offsetAt(next.from(), e);
            sendStartUp(startNext, emit);
        } else {
            Corner c = NoseGeometry.corner(pendingElement, next, e);
            boolean meet = c != null;
            if (!meet) {
                // the offset elements never meet (E172): each ends perpendicular, joined by a straight move
                c = new Corner(pendingElement.offsetAt(pendingElement.to(), e), List.of(),
                        next.offsetAt(next.from(), e), true);
            }
            List<Point> around = new ArrayList<>(c.around());
            around.add(c.startOfSecond());
            close(c.endOfFirst(), around, meet, emit);
            startNext = c.startOfSecond();
        }
        flushHeld(emit);
        pending = b;
        pendingInfo = info;
        pendingElement = next;
        pendingStart = startNext;
        checkArc(next, info);
    }

    /** G40 with a move (or the move after a G40 alone): type A, from the perpendicular offset to the programmed point. */
    private void cancel(CheckedBlock b, NoseInfo info, List<Motion> path, List<CheckedBlock> emit) {
        Motion first = path.get(0);
        arcAtEnd(first, info);
        Point end = closePerpendicular(emit);
        flushHeld(emit);
        Point from = end != null ? tipAt(end) : restartFrom != null ? restartFrom : from(first);
        restartFrom = null;
        emit.add(travel(startingAt(b, first, from), info));
        mode = Mode.OFF;
        exiting = false;
        if (info.side() != NoseSide.OFF) {
            // the move after a G40 alone, into a new G41/G42 in the same block: start again
            arm(info);
        }
    }

    /**
     * A block the control runs without offsetting it ({@link NoseSuspend}): the compensated path ends
     * perpendicular before it, its first move goes from where the tool stands to its programmed end
     * (for G28, to the intermediate point: the offset is cancelled there), the rest as programmed;
     * the next move starts the compensation again (type A), with the nose in force after the block.
     */
    private void suspend(CheckedBlock b, NoseInfo info, List<CheckedBlock> emit) {
        Point stands = restartFrom;
        if (mode == Mode.ACTIVE) {
            Point end = closePerpendicular(emit);
            if (end != null) {
                stands = tipAt(end);
            }
        }
        flushHeld(emit);
        Motion first = null;
        for (Motion m : b.motions()) {
            if (MotionKind.of(m).moves) {
                first = m;
                break;
            }
        }
        if (first != null && stands != null) {
            emit.add(startingAt(b, first, stands));
            stands = null;
        } else {
            emit.add(b);
        }
        mode = Mode.OFF;
        exiting = false;
        arm(info);
        restartFrom = stands; // a block without a move leaves the tool where the path ended
    }

    /**
     * The block as it is, or, when a suspension left the tool off the programmed point
     * ({@link #restartFrom}) and the block moves, with its first move from there.
     */
    private CheckedBlock resumed(CheckedBlock b) {
        if (restartFrom == null) {
            return b;
        }
        for (Motion m : b.motions()) {
            if (MotionKind.of(m).moves) {
                CheckedBlock r = startingAt(b, m, restartFrom);
                restartFrom = null;
                return r;
            }
        }
        return b;
    }

    /** Ends the pending block perpendicular to its element's end (no next move to meet); returns the nose centre there. */
    private Point closePerpendicular(List<CheckedBlock> emit) {
        if (pending == null) {
            return null;
        }
        Point end;
        if (pendingElement == null) {
            Element self = Element.of(path(pending).get(0));
            end = self.length() > 0 ? self.offsetAt(self.to(), e) : self.to();
            sendStartUp(end, emit);
        } else {
            end = pendingElement.offsetAt(pendingElement.to(), e);
            close(end, List.of(), true, emit);
        }
        pending = null;
        pendingElement = null;
        return end;
    }

    /**
     * Sends the pending start-up block (type A), its move ending with the nose centre at
     * {@code end}; the move begins at its programmed start, or where a block without a move under a
     * suspension ({@link #suspend}) left the tool.
     */
    private void sendStartUp(Point end, List<CheckedBlock> emit) {
        Motion m = path(pending).get(0);
        List<Motion> ms = new ArrayList<>(before(pending, m));
        ms.add(line(m, restartFrom != null ? restartFrom : from(m), tipAt(end)));
        restartFrom = null;
        ms.addAll(after(pending, m));
        emit.add(travel(with(pending, ms, pending.end()), pendingInfo));
    }

    /**
     * Sends the pending element offset from its start to {@code end}, then the corner moves to each
     * of {@code around}; E172 when the element runs backwards or ({@code meet} false) its corner has
     * no intersection.
     */
    private void close(Point end, List<Point> around, boolean meet, List<CheckedBlock> emit) {
        Element el = pendingElement;
        if (!meet || !NoseGeometry.forward(el, pendingStart, end)) {
            out.report(pendingInfo.error(Code.E172_NOSE_INTERFERENCE, mm(Math.abs(e))));
        }
        List<Point> corner = new ArrayList<>(around.size());
        for (Point q : around) {
            corner.add(tipAt(q));
        }
        List<Motion> ms = NoseMoves.offset(pending, lead, el.arc(), tipAt(pendingStart), tipAt(end),
                el.arc() ? tipAt(el.centre()) : null, el.arc() ? el.offsetRadius(e) : 0, corner);
        lead = null;
        emit.add(travel(with(pending, ms, pending.end()), pendingInfo));
        pendingStart = null;
    }

    /** E171 when the start-up or cancel move {@code m} is an arc (the control alarms); whether it is one. */
    private boolean arcAtEnd(Motion m, NoseInfo info) {
        Motion.Arc a = MotionKind.arc(m);
        if (a != null) {
            out.report(info.error(Code.E171_NOSE_ARC_START_OR_EXIT, "G0" + (a.clockwise() ? 2 : 3)));
        }
        return a != null;
    }

    /** E173: a concave arc whose offset radius would be nothing or less. */
    private void checkArc(Element el, NoseInfo info) {
        if (el.arc() && el.offsetRadius(e) <= NoseGeometry.NOTHING) {
            out.report(info.error(Code.E173_NOSE_ARC_TOO_TIGHT, mm(el.radius()), mm(Math.abs(e))));
        }
    }

    /** E179, once per block: a compensated move beyond the travel ({@link NoseTravel}). */
    private CheckedBlock travel(CheckedBlock b, NoseInfo info) {
        NoseTravel.check(b, info, profile, out);
        return b;
    }

    private void flushHeld(List<CheckedBlock> emit) {
        emit.addAll(held);
        held.clear();
    }

    private Point tipAt(Point centre) {
        return new Point(centre.x() + tip[0], centre.z() + tip[1]);
    }

    private String mm(double counts) {
        return gcnc.check.geom.NumberText.plain(counts / profile.x().countsPerMm(), 3);
    }
}
