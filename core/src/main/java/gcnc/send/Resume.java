package gcnc.send;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.sim.Sequence;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The program that continues an interrupted run at a {@link ResumePoint}, built from the compiled
 * program's own instructions (docs/run.md, "Resume"):
 * <ol>
 * <li>the program's header ({@code #GCNC}, {@code SH}, {@code VM}, {@code VA}, {@code VD});
 * <li>the state the controller holds at that point as the program set it: the last {@code TOOL=},
 *     the last value of each variable ({@code gline}), every output bit the program switched
 *     ({@code SB}/{@code CB}) at its last value, the last spindle {@code OF} (one a blended
 *     sequence changed on the way counts when the stop is past it); then {@code WT 2000} when the
 *     spindle turns, for it to reach speed (the profile gives no spin-up time). Offsets, units and
 *     feed mode (G94/G95, G96) need nothing: the compiler resolved them into the counts and speeds
 *     of every later line;
 * <li>when the resume point or the axes are inside a vector sequence (a blended group of blocks, or
 *     one motion stopped part way), the rest of that sequence re-planned as a new sequence from
 *     where the axes are: the remaining part of the segment they are on (the line to its end, the
 *     arc from their angle), then the sequence's later segments, each with its own speeds, VPs
 *     measured from the new origin; every trip point still ahead ({@code AV}, with the outputs and
 *     spindle speeds it sets: a coolant switch, a G96 speed) measured on the new path, and, for a rest
 *     longer than the buffer, {@code BGS} after the first fill and a wait for room before each further
 *     batch, as the compile feeds a long sequence ({@link Replan});
 * <li>the program's lines after that sequence (or from the resume point) to its end, unchanged.
 * </ol>
 * The axes must be at the point's start, or on the path of the sequence from there (they stopped
 * on it), or at its end; anywhere else gcnc does not invent a move through the part: E827, whose
 * advice, in program terms, retracts X clear of the part before any Z move.
 */
public final class Resume {
    private final DmcProgram program;
    private final BlockTable blocks;
    private final PositionText where;
    private final double tolerance;

    /** A resume whose refusals give positions in Galil counts alone (no program frames). */
    public Resume(DmcProgram program, double tolerance) {
        this(program, BlockTable.none(), tolerance);
    }

    /**
     * @param blocks    the checker's frame at each line: refusals give positions in program terms
     * @param tolerance how far (counts) the axes may be from the path and still be on it
     */
    public Resume(DmcProgram program, BlockTable blocks, double tolerance) {
        this.program = program;
        this.blocks = blocks;
        this.where = new PositionText(program, blocks);
        this.tolerance = tolerance;
    }

    /** The state the last {@link #plan} sets before it moves: the tool, the output bits, the spindle's speed. */
    private List<Command> restored = List.of();

    /**
     * The state the last {@link #plan} restores before its first motion, as the program had set it at
     * the resume point ({@code TOOL=}, each output bit the program switched, the spindle's {@code OF} or
     * {@code AO}): what {@link ResumeState} holds against the controller.
     */
    public List<Command> restored() {
        return List.copyOf(restored);
    }

    /** What the controller did without the host, as the axes show it (null: nothing to say). */
    private String ranOn;

    /**
     * What the last {@link #plan} found the controller did without the host, for the run's report: "the
     * controller finished the sequence: line 300 to 448" (a link that dropped while it ran on); empty when
     * the axes were where the resume point is.
     */
    public java.util.Optional<String> ranOn() {
        return java.util.Optional.ofNullable(ranOn);
    }

    /** "line A to B" (or "line A") of a sequence's blocks. */
    private String lines(Sequence q) {
        int a = program.sourceLine(q.isThreadPass() ? q.first() : q.pieces().get(0).line());
        int b = program.sourceLine(q.isThreadPass() ? q.first() : q.pieces().get(q.pieces().size() - 1).line());
        return a == b ? "line " + a : "line " + a + " to " + b;
    }

    /** The resume point and the axes of the last {@link #plan}: G96's speed is the surface speed's there. */
    private ResumePoint point;
    private double[] axes;
    /** The compiled program's line the last {@link #plan} picks the program up at, where the axes are. */
    private int resumedAt;

    /**
     * The compiled program's line the last {@link #plan} picks the program up at: the line of the
     * motion the axes stand at the start of or on (with {@link #axes()}, how much of the program's
     * clock is left: {@link Progress#secondsLeft}), or the line after what the controller finished.
     */
    public int resumedAt() {
        return resumedAt;
    }

    /** The axes the last {@link #plan} was made from (Galil counts of the plane). */
    public double[] axes() {
        return axes.clone();
    }

    /** {@code piece}, which takes the program up at compiled line {@code index}. */
    private Download from(int index, Download piece) {
        resumedAt = index;
        return piece;
    }

    public Download plan(ResumePoint at, double[] axes) throws RunFault {
        ranOn = null;
        wayBack = null;
        point = at;
        this.axes = axes.clone();
        int first = program.firstLineOf(at.line());
        if (first < 0) {
            throw fault(at, "line " + at.line() + " has no block that reached the controller (a comment, an empty line"
                    + " or beyond the program): name the line of a block");
        }
        List<DmcProgram.Motion> motions = program.motionsOf(at.line());
        if (at.motion() > motions.size()) {
            throw fault(at, "line " + at.line() + " makes " + motions.size() + " motion" + (motions.size() == 1 ? "" : "s"));
        }
        DmcProgram.Motion m = at.motion() > 0 ? motions.get(at.motion() - 1) : motions.isEmpty() ? null : motions.get(0);
        if (m == null) {
            double[] start = positionAt(first);
            if (near(axes, start)) {
                return from(first, build(first, first, null));
            }
            throw fault(at, "the axes are at " + where.at(at.line(), axes) + " and the block starts at "
                    + where.at(at.line(), start) + ": " + wayTo(at.line(), first, axes, start) + " and resume again");
        }
        Sequence s = m.sequence();
        double[] start = m.start();
        if (m.from() == 0 && near(axes, start)) {
            // the motion starts its sequence: the program from the block's first line (or the motion's), unchanged
            int from = at.motion() > 0 ? s.first() : Math.min(first, s.first());
            return from(from, build(from, from, null));
        }
        if (near(axes, s.end())) {
            ranOn = "the controller finished the sequence: " + lines(s);
            return from(s.last() + 1, build(s.last() + 1, s.last() + 1, null));
        }
        if (s.isThreadPass()) {
            throw fault(at, "a thread pass cannot be entered part way (the spindle and Z are geared at its start): "
                    + wayTo(at.line(), s.first(), axes, start) + " and resume at " + at.line());
        }
        // inside the sequence: from the piece the axes stand at the start of, or on, from this motion on
        for (int k = m.from(); k < s.pieces().size(); k++) {
            Sequence.Piece p = s.pieces().get(k);
            if (near(axes, p.from())) {
                if (k > m.from()) {
                    ranOn = "the controller finished the sequence's blocks: line " + at.line() + " to "
                            + program.sourceLine(s.pieces().get(k - 1).line());
                }
                return from(p.line(), build(s.last() + 1, s.first(), new Replan(program, fill).of(s, k, false, axes, at)));
            }
            if (!near(axes, p.to()) && onPiece(p, axes)) {
                if (k > m.from()) {
                    ranOn = "the controller ran on along the sequence into line " + program.sourceLine(p.line());
                }
                return from(p.line(), build(s.last() + 1, s.first(), new Replan(program, fill).of(s, k, true, axes, at)));
            }
        }
        // a controller that ran on without the host (a dropped link) stands at the end of a later sequence:
        // the first such end after the point (were it a later one with the same end, the passes between
        // are run again over material already cut: the program's own path, never a move through the part)
        List<Sequence> all = program.sequences();
        for (int q = all.indexOf(s) + 1; q < all.size(); q++) {
            Sequence later = all.get(q);
            if (near(axes, later.end())) {
                int last = program.sourceLine(later.isThreadPass() ? later.first()
                        : later.pieces().get(later.pieces().size() - 1).line());
                ranOn = "the controller ran on without the host and finished the sequences: line " + at.line() + " to " + last;
                return from(later.last() + 1, build(later.last() + 1, later.last() + 1, null));
            }
        }
        throw fault(at, "the axes are at " + where.at(at.line(), axes) + ", not on the path of line " + at.line() + " ("
                + where.at(at.line(), start) + " to " + where.at(at.line(), s.end()) + "): "
                + wayTo(at.line(), s.isThreadPass() ? s.first() : s.pieces().get(m.from()).line(), axes, start)
                + " and resume again");
    }

    /** The way back of the last refusal that gave one (null: none); see {@link #wayBack()}. */
    private WayBack wayBack;

    /**
     * The way back to the resume point the last {@link #plan} advised when it refused with E827 because
     * the axes were off the path: the legs {@code gcnc run --way-back} makes.
     */
    public java.util.Optional<WayBack> wayBack() {
        return java.util.Optional.ofNullable(wayBack);
    }

    /** The first compiled line of the sequence the last {@link #wayBack()} goes back to (of its block, without one). */
    private int wayBackFrom;

    /**
     * The first compiled line of the sequence (or block) the last {@link #wayBack()} goes back to: the program
     * before it has cut the stock as it stood, or with more left on it, when the axes left the path.
     */
    public int wayBackFrom() {
        return wayBackFrom;
    }

    /** E827's advice, kept as {@link #wayBack()}: never straight, X away from the part first, then Z, then X. */
    private String wayTo(int line, int index, double[] axes, double[] start) {
        wayBack = WayBack.of(program, where, tolerance, line, index, axes, start);
        wayBackFrom = index;
        for (Sequence q : program.sequences()) {
            if (q.first() <= index && index <= q.last()) {
                wayBackFrom = q.first();
            }
        }
        return wayBack.text();
    }

    /** Where the axes are when program line {@code index} starts. */
    private double[] positionAt(int index) {
        double[] p = null;
        for (Sequence q : program.sequences()) {
            if (q.last() < index) {
                p = q.end();
            }
        }
        if (p == null) {
            Sequence firstMotion = program.sequences().isEmpty() ? null : program.sequences().get(0);
            return firstMotion == null ? new double[] {0, 0} : firstMotion.start();
        }
        return p;
    }

    /**
     * @param from      the first of the program's lines to run unchanged
     * @param stateEnd  the state is what the lines before this one set
     * @param replanned the rest of an interrupted sequence, or null
     */
    private Download build(int from, int stateEnd, Replan.Result replanned) {
        Download.Builder b = new Download.Builder();
        int size = program.size();
        int header = 0;
        while (header < size && program.sourceLine(header) == 0 && !(program.command(header) instanceof Command.End)) {
            // not the homing check: a resumed run starts where the axes stopped, which the sender checks itself
            if (!(program.command(header) instanceof Command.Jump j && j.label().equals("NOHOME"))) {
                b.add(program.command(header), header);
            }
            header++;
        }
        int of = -1;
        int tool = -1;
        Map<Integer, Integer> bits = new TreeMap<>();
        Map<String, Integer> variables = new TreeMap<>();
        List<Integer> state = new ArrayList<>();
        for (int i = header; i < stateEnd && i < size; i++) {
            state.add(i);
        }
        if (replanned != null) {
            state.addAll(replanned.passed());
        }
        for (int i : state) {
            Command c = program.command(i);
            switch (Restore.of(c)) {
                case SPINDLE -> of = i;
                case TOOL -> tool = i;
                case OUTPUT -> bits.put(((Command.Output) c).bit(), i);
                case VARIABLE -> variables.put(((Command.SetVariable) c).name(), i);
                case NOTHING -> {
                }
            }
        }
        restored = new ArrayList<>();
        if (tool >= 0) {
            b.add(program.command(tool), tool);
            restored.add(program.command(tool));
        }
        for (int v : variables.values()) {
            b.add(program.command(v), v);
        }
        for (int bit : bits.values()) {
            b.add(program.command(bit), bit);
            restored.add(program.command(bit));
        }
        if (of >= 0) {
            Command speed = surfaceSpeed(program.command(of));
            b.add(speed, of);
            restored.add(speed);
            double volts = speed instanceof Command.Offset o ? o.volts().value() : ((Command.AnalogOut) speed).volts().value();
            if (volts != 0) {
                b.add(new Command.Wait(2000), of);
            }
        }
        if (replanned != null) {
            Download r = replanned.lines().build(program.lineWidth());
            for (int i = 0; i < r.commands().size(); i++) {
                b.add(r.commands().get(i), r.origin()[i]);
            }
        }
        for (int i = Math.max(from, header); i < size; i++) {
            b.add(program.command(i), i);
        }
        return b.build(program.lineWidth());
    }

    /**
     * The spindle's speed command to restore: under G96 at the resume point, the surface speed's r/min
     * where the axes are (rpm = 1000 V / (pi D), V in m/min and D in mm; 304.8 V under G20; clamped by
     * G50 S and the machine's top speed, as the checker's SpindleSpeed), in the direction of the
     * program's last one; else the program's last one as it was (G97's r/min).
     */
    private Command surfaceSpeed(Command last) {
        BlockTable.Block b = point == null ? null : blocks.at(point.line());
        double[] p = b == null || !b.css() || Double.isNaN(b.surfaceSpeed()) ? null
                : b.program(program.plane().machine(axes));
        double volts = last instanceof Command.Offset o ? o.volts().value() : ((Command.AnalogOut) last).volts().value();
        if (p == null || volts == 0 || rpmPerVolt <= 0) {
            return last;
        }
        double diameterMm = Math.abs(p[0]) * (diameterX ? 1 : 2) * (b.inch() ? 25.4 : 1);
        double rpm = diameterMm > 0 ? (b.inch() ? 304.8 : 1000) * b.surfaceSpeed() / (Math.PI * diameterMm)
                : Double.POSITIVE_INFINITY;
        rpm = Math.min(rpm, Double.isNaN(b.rpmClamp()) ? maxRpm : Math.min(b.rpmClamp(), maxRpm));
        gcnc.dmc.Fixed v = gcnc.dmc.Fixed.fourDecimals(Math.signum(volts) * rpm / rpmPerVolt);
        return last instanceof Command.Offset o ? new Command.Offset(o.channel(), v)
                : new Command.AnalogOut(((Command.AnalogOut) last).output(), v);
    }

    /** The machine's spindle: r/min per volt, top speed, and whether X is programmed as a diameter (G96's speed). */
    private double rpmPerVolt;
    private double maxRpm = Double.POSITIVE_INFINITY;
    private boolean diameterX = true;

    /**
     * The segments a re-planned sequence gives before its {@code BGS} when it is longer than the
     * buffer: the model's buffer less the slot VE takes; without a machine, as many as the interrupted
     * sequence gave (one fed while it ran is fed again from the same fill).
     */
    private int fill = Integer.MAX_VALUE;

    /**
     * This resume with {@code profile}'s spindle, so that G96 is restored as its surface speed (without it: as
     * the r/min last set), and its controller's vector buffer, for a re-planned sequence's feeding.
     */
    public Resume spindle(gcnc.machine.MachineProfile profile) {
        rpmPerVolt = profile.rpmPerVolt();
        maxRpm = profile.maxRpm();
        diameterX = profile.diameterX();
        fill = (int) profile.controllerLimits().model().range(gcnc.machine.GalilModel.Limit.BUFFER_SEGMENTS).max() - 1;
        return this;
    }

    /** The sweep from {@code theta} to {@code end} in the direction of {@code sense}, degrees. */
    static double sweepTo(double theta, double end, double sense) {
        double d = ((end - theta) % 360 + 360) % 360; // [0, 360)
        return sense < 0 && d > 0 ? d - 360 : d;
    }

    private boolean onPiece(Sequence.Piece p, double[] q) {
        return onPiece(p, q, tolerance);
    }

    /** Is {@code q} on piece {@code p}, within {@code tolerance} counts (an arc: on its radius and within its sweep)? */
    static boolean onPiece(Sequence.Piece p, double[] q, double tolerance) {
        if (p instanceof Sequence.Arc a) {
            double r = Math.hypot(q[0] - a.centre()[0], q[1] - a.centre()[1]);
            if (Math.abs(r - a.radius()) > tolerance) {
                return false;
            }
            double ang = Math.toDegrees(Math.atan2(q[1] - a.centre()[1], q[0] - a.centre()[0]));
            double swept = sweepTo(a.theta(), ang, a.delta());
            return Math.abs(swept) <= Math.abs(a.delta()) + 1e-9;
        }
        double[] f = p.from();
        double[] t = p.to();
        double dx = t[0] - f[0];
        double dz = t[1] - f[1];
        double len2 = dx * dx + dz * dz;
        double u = len2 == 0 ? 0 : ((q[0] - f[0]) * dx + (q[1] - f[1]) * dz) / len2;
        if (u < 0 || u > 1) {
            return false;
        }
        return Math.hypot(f[0] + u * dx - q[0], f[1] + u * dz - q[1]) <= tolerance;
    }

    private boolean near(double[] a, double[] b) {
        return Math.hypot(a[0] - b[0], a[1] - b[1]) <= tolerance;
    }

    private static RunFault fault(ResumePoint at, String why) {
        return new RunFault(Code.E827_CANNOT_RESUME, at.line(), false, at, why);
    }
}
