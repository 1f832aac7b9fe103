package gcnc.plan;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.StopAt;
import gcnc.machine.Blending;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * Continuous contouring: consecutive path motions become one vector sequence wherever the machine
 * may keep moving, with a speed for each motion and a speed for each corner (docs/galil.md,
 * "Continuous contouring"). The algorithm, after Grbl's planner.c:
 *
 * <ol>
 * <li><b>What joins.</b> A straight move or an arc joins the sequence being gathered when it is of the
 * same kind (rapid, or feed), in the same program file, and turns from the last one by less than a
 * reversal. Everything else ends the sequence, with its reason ({@link Stop}): a block that changes
 * the tool or switches outputs (except the M codes of the profile's {@code plan.on_the_fly}, coolant
 * by default: those switch where the path reaches their block, {@link Switch}), a dwell, a thread pass (geared, never blended), a rapid after a feed
 * or back, a call into another file, the end of the program, the exact stop the program asks for
 * (G09 after its block, G61 after every motion). A new spindle speed alone (G96 at the
 * next diameter) does not stop a feed: the emitter sets it when the tool reaches that motion.</li>
 * <li><b>The bound.</b> A sequence is as long as its path: the controller takes more segments while it
 * runs (COMALL VM: "Additional segments may be given during the motion when the buffer frees
 * additional spaces"), and the emitter keeps its buffer fed. The planner holds at most
 * 2 × {@link #WINDOW} pieces: when that many are held, it plans them all with the last one ending
 * at rest and hands on the first {@link #WINDOW} (a group that goes on, {@link Step.Group#goesOn});
 * their last exit speed is one the machine can still stop from over the pieces still held, so the
 * next window, whatever joins it, can always stop (Grbl's planner: a look-ahead of N blocks, the
 * newest planned to rest). Also at most {@link #MAX_LENGTH} counts of path in a sequence (the
 * controller refuses one longer than 2^31, TC 31). A sequence that sets something on the way is as long
 * as any other: the emitter writes each trip point ({@code AV}) while the buffer is fed, once its segment
 * is well inside the buffer (GroupWriter). A straight move longer than one VP segment may be
 * ({@link SegmentLimit}) is held as equal pieces, all in the same sequence.</li>
 * <li><b>Speeds.</b> A motion's speed is its feed (the rapid speed for a rapid), an arc's at most
 * √(a·r) so that its centripetal acceleration stays within the machine's. A corner's speed is the
 * junction-deviation speed √(a·δ·sin(θ/2)/(1−sin(θ/2))) (θ the angle between the two directions,
 * δ the profile's {@code corner.deviation}), never above either motion's speed: tangent joints keep
 * the feed, sharp corners slow, a reversal stops.</li>
 * <li><b>Passes.</b> The sequence starts and ends at rest (a window after the first starts at the
 * speed the one before it handed on). A reverse pass from the end lowers each
 * corner to what the machine can still stop from over the motions after it; a forward pass from the
 * start lowers each to what it can reach over the motions before it; so |v_in² − v_out²| ≤ 2·a·L for
 * every motion, a = the smaller of the profile's acceleration and deceleration.</li>
 * </ol>
 * The emitter rounds the speeds to what the controller takes; the simulator replays them and checks
 * every corner again (E332) from the segments it replayed, not from these numbers.
 */
public final class Contouring implements Planner {
    /**
     * The planner's window, pieces: it holds at most twice as many, and hands on this many at a time
     * (a piece is at most two segments: a window is at most 512 segments, about one buffer).
     */
    public static final int WINDOW = 256;
    /** The longest sequence, counts (TC 31 is past 2^31; half of it leaves room for rounding). */
    public static final double MAX_LENGTH = 1L << 30;
    /** A corner slower than this (counts/s) is a reversal: Galil's slowest segment speed is 2. */
    static final double SLOWEST = 2;

    private final MachineProfile profile;
    private final double acceleration;
    private final double deviation;
    /*
     * The held pieces, one entry each in every list and array (paths.size() of them): the block,
     * the motion's index there, its path, whether its spindle speed is set on the way, the outputs
     * switched as the tool reaches it (plan.on_the_fly), and its part of its motion and how many
     * parts it has (SegmentLimit). The numbers are in arrays, not lists of boxes: one piece a motion.
     */
    private final List<CheckedBlock> blocks = new ArrayList<>();
    private final List<PlannedPath> paths = new ArrayList<>();
    private final List<List<Switch>> switchesAt = new ArrayList<>();
    private int[] motions = new int[16];
    private boolean[] spindles = new boolean[16];
    private int[] parts = new int[16];
    private int[] partCounts = new int[16];
    /** Outputs on the fly after the last held motion: they go with the next motion if it joins, else at rest. */
    private final List<Switch> pending = new ArrayList<>();
    /** Whether any held piece sets something on the way (its spindle speed, outputs). */
    private boolean heldOnTheWay;
    /** The speeds at the held pieces' starts, worked out at each flush (reused from one to the next). */
    private double[] entry = new double[16];
    private final Blending blending;
    private final SegmentLimit limit;
    /** What a block asks of the path: a stop, or an output switched on the fly. */
    private final BlockStops stops;
    private double length;
    /**
     * Whether the held pieces continue a sequence of which windows were handed on already, and the
     * speed the last of those ends with (where the first held piece starts); 0 when none was.
     */
    private boolean continuing;
    private double carried;

    Contouring(MachineProfile profile, Blending blending) {
        this.profile = profile;
        this.blending = blending;
        this.limit = SegmentLimit.of(profile);
        this.stops = new BlockStops(profile, blending);
        this.acceleration = Math.min(profile.acceleration(), profile.deceleration());
        this.deviation = blending.deviationMm() * Math.min(profile.x().countsPerMm(), profile.z().countsPerMm());
    }

    @Override
    public void accept(CheckedBlock b, Consumer<Step> out) {
        Stop before = stops.before(b);
        // a new spindle speed alone (G96 following the diameter) is set on the way, not at a stop
        // (whether the block joins is asked last: it plans the block's first motion once more)
        boolean onTheWay = before == Stop.SPINDLE && b.tool().isEmpty() && !stops.stops(b.before()) && !firstRapid(b)
                && joinsFirst(b);
        List<Switch> own = List.of();
        if (before != null && !onTheWay) {
            flush(before, out);
            out.accept(new Step.Before(b));
        } else if (stops.switches(b.before())) {
            // outputs that may switch on the fly (plan.on_the_fly): where the path reaches the block
            Switch s = new Switch(b, b.before(), false);
            if (joinsFirst(b)) {
                own = List.of(s);
            } else if (b.motions().isEmpty() && holding()) {
                pending.add(s); // between two motions: switched where the next one starts, if it joins
            } else {
                flush(firstStop(b), out);
                out.accept(s.atRest());
            }
        }
        List<Motion> ms = b.motions();
        for (int i = 0; i < ms.size(); i++) {
            Motion m = ms.get(i);
            PlannedPath p = PlannedPath.of(m, profile.rapidSpeed(), acceleration);
            if (p == null) {
                flush(m instanceof Motion.Thread ? Stop.THREAD : Stop.DWELL, out);
                out.accept(new Step.Alone(b, i));
                continue;
            }
            if (p.length() < 0.5) {
                // shorter than a count: nothing to write, no direction of its own. Alone when nothing is
                // held; else in the sequence, in its order, turning neither way (the emitter skips it)
                if (paths.isEmpty() || paths.get(paths.size() - 1).rapid() != p.rapid()) {
                    flush(Stop.RAPID_FEED, out);
                    out.accept(new Step.Alone(b, i));
                    continue;
                }
                p = paths.get(paths.size() - 1).standing(p.speed());
            }
            // a straight move longer than one VP takes: equal pieces, one after the other (SegmentLimit)
            int n = m instanceof Motion.Linear ? limit.parts(p.length()) : 1;
            if (!paths.isEmpty()) {
                Stop stop = joins(b, p, n);
                if (stop != null) {
                    flush(stop, out);
                }
            }
            List<Switch> here = List.of(); // (none, nearly always: no list made)
            if (!pending.isEmpty() || !own.isEmpty()) {
                here = new ArrayList<>(pending);
                here.addAll(own);
            }
            pending.clear();
            own = List.of();
            for (int k = 0; k < n; k++) {
                hold(b, i, n == 1 ? p : p.part(n), onTheWay && k == 0, k == 0 ? here : List.of(), k, n);
                if (paths.size() >= 2 * WINDOW) {
                    handOn(out);
                }
            }
            onTheWay = false;
            length += p.length();
            if (b.stopAt() == StopAt.EVERY_MOTION) {
                flush(Stop.EXACT_STOP_MODE, out); // G61: every move ends at rest
            }
        }
        after(b, out);
    }

    /** What the block asks after its motions: a stop at its end (G09), a program stop, outputs at rest or on the fly. */
    private void after(CheckedBlock b, Consumer<Step> out) {
        List<Motion> ms = b.motions();
        if (b.stopAt() == StopAt.BLOCK_END) {
            flush(Stop.EXACT_STOP_BLOCK, out); // G09: the block's move ends at rest
        }
        if (stops.programStop(b.after())) {
            // M00 (M01 with the switch on): the axes at rest before the stop's outputs and the wait
            flush(Stop.PROGRAM_STOP, out);
            out.accept(new Step.After(b));
        } else if (stops.switches(b.after())) {
            int held = paths.size();
            boolean endsHere = held > 0 && blocks.get(held - 1) == b && motions[held - 1] == ms.size() - 1;
            if (!stops.stops(b.after()) && (endsHere || ms.isEmpty() && holding())) {
                // the block's end on the fly: where the next motion starts, if it joins
                pending.add(new Switch(b, b.after(), true));
            } else {
                flush(Stop.OUTPUT, out);
                out.accept(new Step.After(b));
            }
        }
    }

    /** Holds one more piece: part {@code part} of {@code count} of motion {@code motion} of {@code b}. */
    private void hold(CheckedBlock b, int motion, PlannedPath p, boolean spindle, List<Switch> switches, int part, int count) {
        int at = paths.size();
        if (at == motions.length) {
            int size = 2 * at;
            motions = java.util.Arrays.copyOf(motions, size);
            spindles = java.util.Arrays.copyOf(spindles, size);
            parts = java.util.Arrays.copyOf(parts, size);
            partCounts = java.util.Arrays.copyOf(partCounts, size);
        }
        blocks.add(b);
        paths.add(p);
        switchesAt.add(switches);
        heldOnTheWay |= spindle || !switches.isEmpty(); // (Piece#onTheWay, kept as the pieces are held)
        motions[at] = motion;
        spindles[at] = spindle;
        parts[at] = part;
        partCounts[at] = count;
    }

    @Override
    public void finish(Consumer<Step> out) {
        flush(Stop.END, out);
    }

    @Override
    public boolean holding() {
        return !paths.isEmpty();
    }

    @Override
    public List<CheckedBlock> held() {
        List<CheckedBlock> out = new ArrayList<>();
        for (CheckedBlock b : blocks) {
            if (out.isEmpty() || out.get(out.size() - 1) != b) {
                out.add(b);
            }
        }
        return out;
    }

    /** Whether the block's first motion is a path that joins the sequence gathered so far. */
    private boolean joinsFirst(CheckedBlock b) {
        return !paths.isEmpty() && !b.motions().isEmpty() && firstStop(b) == null;
    }

    /** Whether the block's first motion is a rapid. */
    private static boolean firstRapid(CheckedBlock b) {
        return !b.motions().isEmpty() && b.motions().get(0) instanceof Motion.Linear l && l.rapid();
    }

    /**
     * Why the block's first motion cannot join the sequence gathered so far (null: it joins, or
     * nothing is held); {@link Stop#OUTPUT} for a block without motion.
     */
    private Stop firstStop(CheckedBlock b) {
        if (paths.isEmpty()) {
            return null;
        }
        if (b.motions().isEmpty()) {
            return Stop.OUTPUT;
        }
        Motion m = b.motions().get(0);
        PlannedPath p = PlannedPath.of(m, profile.rapidSpeed(), acceleration);
        if (p == null) {
            return m instanceof Motion.Thread ? Stop.THREAD : Stop.DWELL;
        }
        if (p.length() < 0.5) {
            return paths.get(paths.size() - 1).rapid() != p.rapid() ? Stop.RAPID_FEED : null;
        }
        return joins(b, p, m instanceof Motion.Linear ? limit.parts(p.length()) : 1);
    }

    /** Why {@code p}, written as {@code n} pieces, cannot join the sequence gathered so far, or null when it can. */
    private Stop joins(CheckedBlock b, PlannedPath p, int n) {
        PlannedPath last = paths.get(paths.size() - 1);
        if (last.rapid() != p.rapid()) {
            return Stop.RAPID_FEED;
        }
        if (!java.util.Objects.equals(blocks.get(blocks.size() - 1).origin().file(), b.origin().file())) {
            return Stop.CALL;
        }
        if (length + p.length() > MAX_LENGTH) {
            return Stop.LENGTH;
        }
        return corner(last, p) < SLOWEST ? Stop.REVERSAL : null;
    }

    /** The junction-deviation speed of the corner from {@code a} into {@code b}, at most either's speed. */
    double corner(PlannedPath a, PlannedPath b) {
        double cos = -(a.exitX() * b.entryX() + a.exitZ() * b.entryZ()); // Grbl: -1 straight on, +1 back
        return Math.min(Math.min(a.speed(), b.speed()), MARGIN * Blending.junctionSpeed(cos, acceleration, deviation));
    }

    private void flush(Stop stop, Consumer<Step> out) {
        int n = paths.size();
        if (n == 0) {
            release(out);
            return;
        }
        plan(n);
        out.accept(group(n, stop)); // (one copy; the group keeps that list)
        continuing = false;
        carried = 0;
        heldOnTheWay = false;
        release(out);
    }

    /**
     * Hands on the first {@link #WINDOW} held pieces as a group that goes on: all held pieces are
     * planned to rest at the last, so the join's speed is one the pieces still held can stop from.
     */
    private void handOn(Consumer<Step> out) {
        int n = paths.size();
        plan(n);
        double join = entry[WINDOW];
        out.accept(group(WINDOW, null));
        continuing = true;
        carried = join; // (length stays the whole sequence's: MAX_LENGTH bounds the sequence, not a window)
    }

    /** The speeds at the starts of the n held pieces ({@link #entry}): from the carried speed, to rest after the last. */
    private void plan(int n) {
        // entry[i]: the speed at the start of motion i; entry[n]: at the end of the last (rest)
        if (entry.length < n + 1) {
            entry = new double[Math.max(n + 1, 2 * entry.length)];
        }
        double[] entry = this.entry; // reused: every entry up to n is written below
        entry[0] = carried;
        entry[n] = 0;
        for (int i = 1; i < n; i++) {
            entry[i] = corner(paths.get(i - 1), paths.get(i));
        }
        for (int i = n - 1; i >= 1; i--) { // reverse pass: each corner one can still stop from
            entry[i] = Math.min(entry[i], Math.sqrt(entry[i + 1] * entry[i + 1] + 2 * acceleration * usable(i)));
        }
        for (int i = 1; i < n; i++) { // forward pass: each corner one can reach
            entry[i] = Math.min(entry[i], Math.sqrt(entry[i - 1] * entry[i - 1] + 2 * acceleration * usable(i - 1)));
        }
    }

    /**
     * The first {@code k} held pieces with their planned speeds, as a group ending for {@code stop}
     * (null: the sequence goes on), taken off the held ones.
     */
    private Step.Group group(int k, Stop stop) {
        Piece[] pieces = new Piece[k];
        boolean onTheWay = false;
        for (int i = 0; i < k; i++) {
            pieces[i] = new Piece(blocks.get(i), motions[i], paths.get(i).speed(), entry[i + 1],
                    paths.get(i).length(), spindles[i], switchesAt.get(i), parts[i], partCounts[i]);
            onTheWay |= pieces[i].onTheWay();
        }
        Step.Group g = new Step.Group(List.of(pieces), stop, stop == null ? onTheWay : heldOnTheWay, continuing,
                stop == null);
        int left = paths.size() - k;
        if (left == 0) {
            switchesAt.clear();
            blocks.clear();
            paths.clear();
            length = 0;
        } else {
            switchesAt.subList(0, k).clear();
            blocks.subList(0, k).clear();
            paths.subList(0, k).clear();
            System.arraycopy(motions, k, motions, 0, left);
            System.arraycopy(spindles, k, spindles, 0, left);
            System.arraycopy(parts, k, parts, 0, left);
            System.arraycopy(partCounts, k, partCounts, 0, left);
            heldOnTheWay = false; // of the pieces still held (a window handed on took its own)
            for (int i = 0; i < left; i++) {
                heldOnTheWay |= spindles[i] || !switchesAt.get(i).isEmpty();
            }
        }
        return g;
    }

    /** The outputs waiting for a next motion that did not join: switched at rest, in program order. */
    private void release(Consumer<Step> out) {
        for (Switch s : pending) {
            out.accept(s.atRest());
        }
        pending.clear();
    }

    /**
     * The length of motion i the passes count on: its length less {@link #ROUNDING} counts, since
     * the emitter writes whole counts and a short segment may come out that much shorter.
     */
    private double usable(int i) {
        return Math.max(0, paths.get(i).length() - ROUNDING);
    }

    /** How much shorter a segment may be written than planned (its two ends rounded to whole counts). */
    static final double ROUNDING = 2;
    /**
     * The share of the junction speed the planner uses: the controller's corner is between segments
     * rounded to whole counts and arcs of printed angles, whose directions differ a little from the
     * program's; the simulator checks the written ones (E332).
     */
    static final double MARGIN = 0.9;
}
