package gcnc.send;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.sim.Sequence;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * The program form (galil-controller.md §6.2, 1): halt the threads ({@code HX}), download the
 * program ({@code DL}), read it back ({@code UL}) and compare line by line, byte for byte, run it
 * ({@code XQ #GCNC,0}) and follow it by polling the line thread 0 executes ({@code _XQ0}) and the
 * axes ({@code TP}) until the thread ends; then {@code _TC} tells an end from an error stop. In step
 * mode (the thesis's Trace) each G-code block's lines are downloaded and run as a program of their
 * own, after Enter. The program must fit the controller's program memory (checked in pre-flight).
 *
 * @param pollMs       how often (ms) the controller is asked where the program is
 * @param tolerance    how far (counts) the axes may end from the program's end point
 * @param stallSeconds how long the axes may stand still inside a vector sequence (no feed hold)
 *                     before the run is stopped as stalled
 */
public record ProgramForm(int pollMs, double tolerance, double stallSeconds) implements Delivery {
    @Override
    public String name() {
        return "program";
    }

    @Override
    public int linesNeeded(Download piece, DmcProgram program, boolean step) {
        return step ? steps(piece, program).stream().mapToInt(p -> p.lines().size()).max().orElse(0) : piece.lines().size();
    }

    @Override
    public void run(Download piece, MachineLink c, Progress progress, Operator op, boolean step, boolean dryRun)
            throws RunFault, IOException, InterruptedException {
        if (!step) {
            send(piece, c, progress, op, dryRun);
            return;
        }
        for (Download block : steps(piece, progress.program())) {
            progress.pointAt(firstBlockLine(block, progress.program()));
            int at = progress.executingLine();
            BlockTable.Block b = progress.blocks().at(at);
            progress.events().accept(new Event.StepWait(at, b == null ? null : b.number()));
            while (!op.awaitEnter()) {
                if (op.stopped()) {
                    // exit 3 even before the first block: the operator stopped a run, and its resume command is printed
                    throw new RunFault(Code.E828_STOPPED_BY_OPERATOR, progress.executingLine(), true,
                            progress.executingLine());
                }
            }
            send(block, c, progress, op, dryRun);
        }
    }

    /** The first of the piece's lines that came from a G-code block (the header's come from none). */
    private static int firstBlockLine(Download p, DmcProgram program) {
        for (int o : p.origin()) {
            if (program.sourceLine(o) > 0) {
                return o;
            }
        }
        return p.originOf(0);
    }

    /**
     * The piece cut into G-code blocks, each a program of its own: {@code #GCNC}, the block's lines,
     * {@code EN}. The header goes with the first block, the footer with the last.
     */
    static List<Download> steps(Download piece, DmcProgram program) {
        List<Download> out = new ArrayList<>();
        List<Command> lines = piece.commands();
        int i = 0;
        while (i < lines.size()) {
            Download.Builder b = new Download.Builder();
            int first = piece.originOf(i);
            if (!(lines.get(i) instanceof Command.Label)) {
                b.add(new Command.Label("GCNC"), first);
            }
            int source = -1;
            int j = i;
            for (; j < lines.size(); j++) {
                int s = program.sourceLine(piece.originOf(j));
                if (s > 0 && source < 0) {
                    source = s;
                } else if (s > 0 && s != source) {
                    break;
                }
                b.add(lines.get(j), piece.originOf(j));
            }
            // the footer (source line 0 after the last block) stays with the last block
            if (j < lines.size() || !lines.subList(i, j).stream().anyMatch(l -> l instanceof Command.End)) {
                if (!(lines.get(j - 1) instanceof Command.End)) {
                    b.add(new Command.End(), piece.originOf(j - 1));
                }
                // the program's routines (#NOHOME, #CMDERR ...: the labels after its EN) with every step,
                // since the header's and the blocks' jumps name them
                for (int k = routines(lines); k < lines.size(); k++) {
                    b.add(lines.get(k), piece.originOf(k));
                }
            }
            out.add(b.build(program.lineWidth()));
            i = j;
        }
        return out;
    }

    /** The index of the first line after the program's first {@code EN} (its routines); the size when none. */
    private static int routines(List<Command> lines) {
        for (int k = 0; k < lines.size(); k++) {
            if (lines.get(k) instanceof Command.End) {
                return k + 1;
            }
        }
        return lines.size();
    }

    private void send(Download piece, MachineLink c, Progress progress, Operator op, boolean dryRun)
            throws RunFault, IOException, InterruptedException {
        c.halt();
        GalilClient.Reply dl = c.client().download(piece.lines());
        if (!dl.ok()) {
            throw c.refused("DL", 0, progress.hasStarted());
        }
        List<String> back = c.client().upload();
        compare(piece.lines(), back, progress);
        progress.events().accept(new Event.Downloaded(piece.lines().size(), true));
        if (dryRun) {
            return;
        }
        // VR stays set on the controller: a run stopped during a feed hold left it at 0, and the next run
        // (its resume) would stand still; each run starts at the operator's override
        c.ratio(op.override());
        c.execute();
        progress.started();
        follow(piece, c, progress, op);
    }

    /** The read-back must be the download, line for line and byte for byte (line ends aside). */
    static void compare(List<String> sent, List<String> back, Progress progress) throws RunFault {
        int n = Math.max(sent.size(), back.size());
        for (int i = 0; i < n; i++) {
            String s = i < sent.size() ? sent.get(i) : "";
            String r = i < back.size() ? back.get(i) : "";
            if (!s.equals(r)) {
                throw new RunFault(Code.E824_READBACK_DIFFERS, 0, progress.hasStarted(), i + 1,
                        GalilClient.printable(s), GalilClient.printable(r));
            }
        }
    }

    /**
     * A thread that ended without an error code may still have been cut short: a limit switch
     * without a #LIMSWI routine stops the motion and the program (COMALL: "without it the controller
     * issues ST"). The axes must be where the piece's last motion ends; else the stop code says why.
     */
    private void endedAtItsEnd(Download piece, int lastXq, MachineLink c, Progress progress, Operator op)
            throws IOException, RunFault {
        Sequence last = null;
        for (int o : piece.origin()) {
            Sequence s = progress.program().sequenceAt(o);
            if (s != null) {
                last = s;
            }
        }
        if (last == null) {
            return;
        }
        double[] at = c.position();
        if (Math.hypot(at[0] - last.end()[0], at[1] - last.end()[1]) <= tolerance) {
            progress.at(last.last(), at, op);
            return;
        }
        int code = c.stopCode();
        settled(piece, lastXq, c, progress, op);
        c.stopAll();
        PositionText where = new PositionText(progress.program(), progress.blocks());
        throw new RunFault(Code.E825_NOT_READY, progress.executingLine(), true, "it ended during line "
                + progress.executingLine() + " with the axes at " + where.at(progress.executingLine(), at) + ", not at the end "
                + where.at(progress.executingLine(), last.end()) + " (stop code " + code + ": " + MachineLink.stopReason(code) + ")");
    }

    /**
     * The compiled command thread 0 stands at on the controller's line {@code xq}, in a routine after
     * the program's EN too ({@code #PSTOP}: a program stop's wait), or -1 beyond the piece.
     */
    static int standing(Download piece, int xq) {
        return piece.originOf(piece.lastOf(xq));
    }

    /**
     * The compiled instruction executing when thread 0 is at the controller's line {@code xq} and the
     * sequence's segment counter {@code _CSS} reads {@code css} (from zero): the line's last command, except in a vector sequence, where
     * the thread waits at {@code AMS} while the segments run: there the segment executing names the
     * line, so that a blended sequence's blocks are followed one by one; before its {@code BGS} the
     * sequence's first segment is next. -1 when the line is one of the program's routines (after its
     * {@code EN}: #LIMSWI, #FAULT ...), where a fault sent the thread while the axes come to rest: no
     * block executes there, and the last poll's block stands.
     */
    static int executing(Download piece, int xq, int css, DmcProgram program) {
        int at = piece.lastOf(xq); // a packed line ends at its wait: that is where the thread stands
        if (at >= routines(piece.commands())) {
            return -1;
        }
        Download.Segments segments = piece.segmentsAt(at, program);
        if (segments == null || segments.origins().length == 0) {
            return piece.originOf(at);
        }
        if (!segments.begun() || segments.origins().length == 1) {
            return segments.origins()[0];
        }
        return segments.executing(css);
    }

    /**
     * After a stop, where the machine came to rest: the axes ({@code TP}) on the path of the first
     * vector sequence, from the line of a block thread 0 was at when last polled ({@code lastXq}) on, whose
     * segments they stand on, and in it the segment {@code _CSS} names (it keeps its number after
     * the sequence ended). Between polls the program may have run on into the next sequence, or a
     * blended sequence through several short segments, so the blocks completed and executing are
     * reported from where the machine stopped, not from the last poll. Axes on no sequence's path (a
     * thread pass, a reply that fails) leave the last poll's.
     */
    private void settled(Download piece, int lastXq, MachineLink c, Progress progress, Operator op) {
        try {
            double[] at = c.position();
            DmcProgram program = progress.program();
            int origin = progress.executingIndex();
            for (int j = Math.max(piece.firstOf(lastXq), 0); j < piece.commands().size(); j++) {
                if (!(program.command(piece.originOf(j)) instanceof Command.AwaitSequence)) {
                    continue;
                }
                Download.Segments segments = piece.segmentsAt(j, program);
                if (segments != null && onPath(segments, at, program)) {
                    origin = segments.origins().length == 1 ? segments.origins()[0] : segments.executing(c.segment());
                    break;
                }
            }
            progress.at(origin, at, op);
        } catch (IOException e) {
            // the link failed as well: the report names what the last poll saw
        }
    }

    /** Are the axes on one of the sequence's segments (as compiled: a re-planned one lies on its original)? */
    private boolean onPath(Download.Segments segments, double[] at, DmcProgram program) {
        for (int o : segments.origins()) {
            Sequence s = program.sequenceAt(o);
            int k = s == null ? -1 : s.pieceAt(o);
            if (k >= 0 && Resume.onPiece(s.pieces().get(k), at, tolerance)) {
                return true;
            }
        }
        return false;
    }

    /** Polls until thread 0 ends, applying the operator's hold, override and stop between polls. */
    private void follow(Download piece, MachineLink c, Progress progress, Operator op)
            throws RunFault, IOException, InterruptedException {
        FeedHold hold = new FeedHold();
        StallWatch stall = new StallWatch(stallSeconds);
        int lastXq = -1;
        int announced = -1; // the program stop announced last (its call's line): once each
        while (true) {
            if (op.stopped()) {
                c.stopAll();
                settled(piece, lastXq, c, progress, op);
                throw new RunFault(Code.E828_STOPPED_BY_OPERATOR, progress.executingLine(), true,
                        progress.executingLine());
            }
            hold.apply(c, progress, op);
            int[] where = c.executingAndSegment();
            int xq = where[0];
            if (xq < 0) {
                int tc = c.errorCode();
                if (tc != 0) {
                    int ed = c.errorLine();
                    // which command of a packed line failed the controller does not say: the line's first
                    int origin = piece.originOf(piece.firstOf(ed));
                    progress.at(origin, null, op);
                    RunFault f = c.refused(origin >= 0 ? "'" + piece.lines().get(ed) + "'" : "the program", progress.executingLine(), true);
                    c.stopAll();
                    throw f;
                }
                endedAtItsEnd(piece, lastXq, c, progress, op);
                return;
            }
            double[] at = c.position();
            int origin = executing(piece, xq, where[1], progress.program());
            if (progress.program().inProgramStop(standing(piece, xq))) {
                // a program stop (M00; M01 with the switch on): the block of its call, at rest, waits for the operator
                int call = progress.program().programStopFrom(progress.executingIndex());
                if (call >= 0 && call != announced) {
                    announced = call;
                    progress.at(call, at, op);
                    ProgramStopWait.await(c, progress, op, call, pollMs,
                            () -> progress.program().inProgramStop(standing(piece, c.executing())));
                }
                Thread.sleep(pollMs);
                continue;
            }
            int fed = piece.fedSequenceOn(xq, progress.program());
            // thread 0 inside a sequence fed while it runs, past its BGS and before its VE, and the sequence no
            // longer moving: its buffer ran dry (E890), as the stream form's host sees it before sending VE.
            // _XQ0 is read again after _BGS: still on a line of the same fed sequence, the thread was before
            // VE when _BGS read 0 (a normal end comes only after VE). The manuals are silent on how a program
            // thread goes on after an underrun (M13X8-74 says only that the motion stops at the last vector):
            // the virtual Galil's takes the next segments as a new sequence, so the stop is made here.
            if (fed >= 0 && c.client().number("_BGS") == 0
                    && piece.fedSequenceOn(c.executing(), progress.program()) == fed) {
                throw Starvation.fault(piece.segmentsAt(piece.lastOf(xq), progress.program()).origins(), c, progress, op);
            }
            if (origin >= 0) {
                // a poll in a fault's routine leaves the line to search for the stop from (settled) at the block's
                lastXq = xq;
            }
            progress.at(origin, at, op);
            // a hold, a dwell and a thread pass's wait for the spindle are not stalls
            Sequence s = progress.program().sequenceAt(progress.executingIndex());
            if (stall.stalled(at, s != null && !s.isThreadPass() && !hold.held() && op.override() > 0)) {
                c.stopAll();
                settled(piece, lastXq, c, progress, op);
                throw stall.fault(progress.executingLine());
            }
            Thread.sleep(pollMs);
        }
    }
}
