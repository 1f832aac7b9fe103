package gcnc.send;

import gcnc.sim.Sequence;

/**
 * Where the run is, as the last poll saw it: the compiled program's line executing, hence the
 * G-code block executing and the one completed before it; and the events that say so (a
 * {@link Event.Block} when the block changes, a {@link Event.Status} per poll).
 */
public final class Progress {
    private final DmcProgram program;
    private final BlockTable blocks;
    private final EventSink events;
    private int executing = -1;
    private int lastBlock = -1;
    private boolean started;
    /** Where the axes were last seen (Galil plane counts), null before any poll. */
    private double[] axes;
    /** The first fault a routine of the program reported (an unsolicited {@link gcnc.dmc.FaultMessage}), or null. */
    private volatile gcnc.dmc.FaultMessage.Fault fault;
    /** Whether {@link #axes} were read after the stop ({@link #axes(double[])}), not only at the last poll. */
    private boolean readAfterStop;
    private final long began = System.nanoTime();

    /** How far (counts) the axes may be from a sequence's start and still stand at it. */
    private final double tolerance;

    public Progress(DmcProgram program, BlockTable blocks, EventSink events) {
        this(program, blocks, events, 3);
    }

    /** @param tolerance how far (counts) the axes may be from a point and still be at it ({@link Sender#tolerance()}) */
    public Progress(DmcProgram program, BlockTable blocks, EventSink events, double tolerance) {
        this.tolerance = tolerance;
        this.program = program;
        this.blocks = blocks;
        this.events = events;
    }

    public DmcProgram program() {
        return program;
    }

    public BlockTable blocks() {
        return blocks;
    }

    public EventSink events() {
        return events;
    }

    /** The program was started on the controller: from now on a stop leaves something to resume. */
    public void started() {
        started = true;
    }

    public boolean hasStarted() {
        return started;
    }

    /** The compiled program's line executing now (0-based), -1 before the first poll. */
    public int executingIndex() {
        return executing;
    }

    /** G-code line of the block executing (0: none yet). */
    public int executingLine() {
        return executing < 0 ? 0 : program.sourceLine(executing);
    }

    /** G-code line of the last block completed (0: none). */
    public int completedLine() {
        return executing < 0 ? 0 : program.blockBefore(executing);
    }

    /**
     * Where a resume continues: the block executing and, when it makes several motions, the one it
     * was in ({@code N:K}); the block's start when no motion of it had begun. In a blended sequence
     * the executing line is the segment's ({@code _CSS}), so N is the block of that segment.
     */
    public ResumePoint resumePoint() {
        int e = Math.max(executing, 0);
        Sequence run = program.sequenceAt(e);
        if (run != null && !run.isThreadPass() && !run.pieces().isEmpty() && axes != null
                && Math.hypot(axes[0] - run.start()[0], axes[1] - run.start()[1]) <= tolerance) {
            // nothing of the sequence moved (a segment refused while it was queued, a stop before its BGS):
            // it resumes at its first block, where the axes stand, not at the segment the host had reached
            e = run.pieces().get(0).line();
        }
        int line = program.sourceLine(e);
        if (line == 0) {
            // the header or the footer: the first block, or nothing left to do after the last
            for (int i = e; i < program.size(); i++) {
                if (program.sourceLine(i) > 0) {
                    return new ResumePoint(program.sourceLine(i), 0);
                }
            }
            return null;
        }
        Sequence s = program.sequenceAt(e);
        java.util.List<DmcProgram.Motion> all = program.motionsOf(line);
        int piece = s == null ? -1 : s.isThreadPass() ? 0 : s.pieceAt(e);
        int k = -1;
        int done = 0;
        for (int i = 0; i < all.size(); i++) {
            DmcProgram.Motion m = all.get(i);
            if (s != null && m.sequence() == s && (s.isThreadPass() || piece == m.from())) {
                k = i;
            }
            if (m.sequence().last() < e) {
                done = i + 1;
            }
        }
        if (k < 0) {
            // between motions (an output, a dwell): after the last motion of the block already done, if any
            k = done - 1;
        }
        return new ResumePoint(line, all.size() <= 1 || k <= 0 ? 0 : k + 1);
    }

    /** The line about to run (step mode, before its Enter): where a stop then says the run was. */
    public void pointAt(int index) {
        executing = index;
    }

    /** The axes read after a stop (Galil plane counts): what {@link #resumePoint} judges by ({@link #settle}). */
    private void axes(double[] counts) {
        if (counts != null) {
            axes = counts.clone();
            readAfterStop = true;
        }
    }

    /**
     * After a stop, the axes read where it left them ({@code TP}), and the block they stand in: the
     * piece of the sequence executing when they are on it (where the last poll saw them), else the
     * first piece from that sequence on (from the program's start before any poll) whose path they
     * are on. Between the last poll and the stop the program may have run on (a refused or garbled
     * poll, a high speed, a long poll period), so the report and the resume point are where the
     * machine stopped; axes on no path (a thread pass, a move off the program) leave the last poll's.
     */
    public void settle(double[] counts) {
        axes(counts);
        if (counts == null) {
            return;
        }
        // before the first poll (a first poll refused), from the program's start
        int from = Math.max(executing, 0);
        Sequence now = program.sequenceAt(from);
        int k = now == null || executing < 0 ? -1 : now.pieceAt(from);
        if (k >= 0 && Resume.onPiece(now.pieces().get(k), counts, tolerance)) {
            return;
        }
        for (Sequence s : program.sequences()) {
            int line = s.last() < from || s.isThreadPass() ? -1 : pieceOn(s, s.pieces().size(), counts);
            if (line >= 0) {
                executing = line;
                return;
            }
        }
    }

    /** The compiled line of the first of {@code s}'s first {@code count} pieces whose path the axes are on, or -1. */
    private int pieceOn(Sequence s, int count, double[] counts) {
        for (int j = 0; j < count; j++) {
            if (Resume.onPiece(s.pieces().get(j), counts, tolerance)) {
                return s.pieces().get(j).line();
            }
        }
        return -1;
    }

    /** Whether {@link #where} is the last poll's position: nothing was read after the stop (the link no longer answered). */
    public boolean wherePolled() {
        return !readAfterStop;
    }

    /**
     * Where the axes were last read (after a stop, else at the last poll: {@link #wherePolled}) in the
     * program's terms, in the frame of the block executing (or the last completed), then the Galil
     * counts; null when they were never read.
     */
    public String where() {
        if (axes == null) {
            return null;
        }
        int line = executingLine() > 0 ? executingLine() : completedLine();
        return new PositionText(program, blocks).at(line, axes);
    }

    /** An unsolicited line from the controller: a fault routine's message is kept ({@link #controllerFault}). */
    public void heard(String line) {
        if (fault == null) {
            gcnc.dmc.FaultMessage.read(line).ifPresent(f -> fault = f);
        }
    }

    /** The first fault a routine of the program reported on the controller (it then stopped the axes and the spindle). */
    public java.util.Optional<gcnc.dmc.FaultMessage.Fault> controllerFault() {
        return java.util.Optional.ofNullable(fault);
    }

    /**
     * A poll's piece (from {@code _CSS}) held against the axes read with it: at a sequence's start the
     * count can still be the sequence before's (the controller keeps it after a sequence ends, and
     * sets it anew only once the new one moves), naming a later piece than the axes are on; then the
     * earlier piece of the same sequence they are on is taken. Anything else stands as polled.
     */
    private int onTheAxes(int index, double[] counts) {
        Sequence s = program.sequenceAt(index);
        if (s == null || s.isThreadPass() || counts == null) {
            return index;
        }
        int k = s.pieceAt(index);
        if (k <= 0 || Resume.onPiece(s.pieces().get(k), counts, tolerance)) {
            return index;
        }
        int earlier = pieceOn(s, k, counts);
        return earlier >= 0 ? earlier : index;
    }

    /** A poll: {@code index} executing (compiled program's line), the axes at {@code counts}. */
    public void at(int index, double[] counts, Operator operator) {
        if (index >= 0) {
            executing = onTheAxes(index, counts);
        }
        if (counts != null) {
            axes = counts.clone();
        }
        int line = executingLine();
        BlockTable.Block b = blocks.at(line);
        if (line != lastBlock && line > 0) {
            lastBlock = line;
            events.accept(new Event.Block(line, b == null ? null : b.number(), completedLine()));
        }
        double total = program.totalSeconds();
        double left = secondsLeft(executing, counts);
        double done = total - left;
        double[] machine = counts == null ? null : program.plane().machine(counts);
        double[] prog = b == null || machine == null ? null : b.program(machine);
        events.accept(new Event.Status(executing + 1, line, b == null ? null : b.number(),
                program.sourceFile(executing), prog, counts, b == null ? Double.NaN : b.feed(), b != null && b.perRev(),
                b != null && b.inch(), b == null ? Double.NaN : b.rpm(), b == null ? null : spindle(b.spindle()),
                total <= 0 ? 0 : Math.min(1, done / total), left, operator.override(),
                operator.held()));
    }

    /**
     * The program's clock left from compiled line {@code index} with the axes at {@code counts} (how far
     * along its motion they are): what the status line shows there, and a resume's estimate.
     */
    public double secondsLeft(int index, double[] counts) {
        return Math.max(0, program.totalSeconds() - program.secondsBefore(Math.max(index, 0)) - partDone(index, counts));
    }

    /** Seconds of the motion of compiled line {@code index} already done, from how far along it the axes are (the chord, for arcs). */
    private double partDone(int index, double[] counts) {
        Sequence s = counts == null || index < 0 ? null : program.sequenceAt(index);
        if (s == null || s.seconds() <= 0) {
            return 0;
        }
        int k = s.pieceAt(index);
        double total = s.lengthBefore(s.pieces().size());
        if (k >= 0 && total > 0) {
            // a blended sequence: the path of the segments before the executing one, and along it
            Sequence.Piece p = s.pieces().get(k);
            double along = Math.min(p.length(), Replan.along(p, counts));
            return s.seconds() * Math.min(1, (s.lengthBefore(k) + along) / total);
        }
        double from = Math.hypot(counts[0] - s.start()[0], counts[1] - s.start()[1]);
        double to = Math.hypot(counts[0] - s.end()[0], counts[1] - s.end()[1]);
        return from + to == 0 ? 0 : s.seconds() * from / (from + to);
    }

    private static String spindle(int m) {
        return switch (m) {
            case 3 -> "cw";
            case 4 -> "ccw";
            case 5 -> "stop";
            default -> null;
        };
    }

    public double seconds() {
        return (System.nanoTime() - began) / 1e9;
    }
}
