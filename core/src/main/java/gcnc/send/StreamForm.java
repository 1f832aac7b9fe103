package gcnc.send;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.CommandKind;
import gcnc.dmc.SequencePart;
import gcnc.dmc.StreamRole;
import gcnc.dmc.StreamSplit;
import gcnc.send.PieceSplit.Sent;
import gcnc.sim.Sequence;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * The stream form (docs/galil.md, "Two forms"; docs/run.md): the resident program (set-up,
 * handlers, wait routines, the blocks that must run inside the controller) downloaded, read back
 * and run ({@code XQ #GCNC,0}) to its {@code gready=1}, then every other command sent through the
 * command line, one at a time, each reply checked. Segments go into the vector buffer only while it
 * has room ({@code _LMS}, one slot kept for {@code VE}), so no more are in flight than it holds; the
 * waits the stream holds are the host's ({@link StreamRole#HOST}): {@code AMS} polls {@code _BGS},
 * {@code WT} waits on the host's clock, {@code AV} polls {@code _AVS} (from the sequence's start, where
 * {@code AV} is from the last {@code AV}: the host adds them up), {@code JS #L} runs the resident
 * routine in thread 0 and polls {@code _XQ0}. While a sequence runs, the segment executing
 * ({@code _CSS}) names the G-code block, as in the program form.
 *
 * <p>The split is the compile's own ({@link StreamSplit}) applied to the piece being run, so a
 * resume (a piece that starts at the resume point) is streamed the same way ({@link PieceSplit}).
 */
public final class StreamForm implements Delivery {
    private final int pollMs;
    private final double tolerance;
    private final double stallSeconds;

    public StreamForm(int pollMs, double tolerance, double stallSeconds) {
        this.pollMs = pollMs;
        this.tolerance = tolerance;
        this.stallSeconds = stallSeconds;
    }

    @Override
    public String name() {
        return "stream";
    }

    @Override
    public int linesNeeded(Download piece, DmcProgram program, boolean step) {
        return splitOnce(piece, program).residentLines(program.lineWidth()).size();
    }

    /** The piece pre-flight counted and the run sends: split once for both. */
    private Download splitPiece;
    private PieceSplit splitOfPiece;

    private PieceSplit splitOnce(Download piece, DmcProgram program) {
        if (piece != splitPiece) {
            splitOfPiece = PieceSplit.of(piece, program);
            splitPiece = piece;
        }
        return splitOfPiece;
    }

    @Override
    public void run(Download piece, MachineLink c, Progress progress, Operator op, boolean step, boolean dryRun)
            throws RunFault, IOException, InterruptedException {
        PieceSplit split = splitOnce(piece, progress.program());
        List<String> resident = split.residentLines(progress.program().lineWidth());
        c.halt();
        GalilClient.Reply dl = c.client().download(resident);
        if (!dl.ok()) {
            throw c.refused("DL", 0, progress.hasStarted());
        }
        ProgramForm.compare(resident, c.client().upload(), progress);
        progress.events().accept(new Event.Downloaded(resident.size(), true));
        if (dryRun) {
            return;
        }
        setUp(c, progress, op);
        Feed feed = new Feed(c, progress, op);
        int waited = -1;
        for (Sent s : split.stream()) {
            int line = progress.program().sourceLine(s.origin());
            if (step && line > 0 && line != waited) {
                waited = line;
                stepWait(s.origin(), progress, op);
            }
            feed.run(s);
        }
    }

    /** Runs the resident set-up ({@code XQ #GCNC,0}) to its end; {@code gready} 0 means it stopped (the homing check). */
    private void setUp(MachineLink c, Progress progress, Operator op) throws IOException, RunFault, InterruptedException {
        // VR stays set on the controller: a run stopped during a feed hold left it at 0 (as ProgramForm)
        c.ratio(op.override());
        c.execute();
        while (c.executing() >= 0) {
            if (op.stopped()) {
                c.stopAll();
                throw new RunFault(Code.E828_STOPPED_BY_OPERATOR, 0, false, 0);
            }
            Thread.sleep(pollMs);
        }
        int tc = c.errorCode();
        if (tc != 0) {
            throw c.refused("the resident program's set-up", 0, false);
        }
        if (c.client().number(StreamSplit.READY) != 1) {
            throw new RunFault(Code.E825_NOT_READY, 0, false, "the resident program's set-up stopped before its end"
                    + " (" + StreamSplit.READY + " = 0): the axes are not at home (#NOHOME); home the machine, then run again");
        }
    }

    private static void stepWait(int origin, Progress progress, Operator op) throws RunFault, InterruptedException {
        progress.pointAt(origin);
        int at = progress.executingLine();
        BlockTable.Block b = progress.blocks().at(at);
        progress.events().accept(new Event.StepWait(at, b == null ? null : b.number()));
        while (!op.awaitEnter()) {
            if (op.stopped()) {
                throw new RunFault(Code.E828_STOPPED_BY_OPERATOR, at, true, at);
            }
        }
    }

    /** The host's side of the stream: sends, feeds the buffer, carries out the waits, follows the machine. */
    private final class Feed {
        private final MachineLink c;
        private final Progress progress;
        private final Operator op;
        /** The compiled lines of the segments of the sequence being sent, in order: {@code _CSS} = k is {@code segments.get(k)}. */
        private final List<Integer> segments = new ArrayList<>();
        /** The last segment's end of the sequence being sent (counts, Galil plane), from the compiled program. */
        private double[] end;
        private final FeedHold hold = new FeedHold();
        /** Vector buffer slots free as last counted; 0 = ask the controller. */
        private int free;
        /**
         * The trip point of the last AV of the sequence running, counts of path from its start: AV is
         * relative (command reference AV, "from the start of a coordinated move sequence or from the
         * last AV command") while {@code _AVS}, which the host polls, is "the vector distance from the
         * start of the sequence", so the host waits for the sum of the sequence's AVs so far.
         */
        private long tripped;
        /**
         * Whether the sequence being sent was started ({@code BGS}) before its {@code VE}: it is fed while
         * it runs, and must not end before VE is sent (an empty buffer then is a starvation, E890).
         */
        private boolean feeding;
        private boolean vectorEnded;

        Feed(MachineLink c, Progress progress, Operator op) {
            this.c = c;
            this.progress = progress;
            this.op = op;
        }

        void run(Sent s) throws IOException, RunFault, InterruptedException {
            Command cmd = s.command();
            between();
            switch (StreamRole.of(cmd)) {
                case SEND -> send(s);
                case HOST -> host(s);
                case EMBED -> throw new IllegalStateException("the split leaves no embedded command in the stream: " + cmd);
            }
        }

        private void send(Sent s) throws IOException, RunFault, InterruptedException {
            Command cmd = s.command();
            SequencePart part = SequencePart.of(cmd);
            if (part == SequencePart.SPEED) {
                segments.clear();
            }
            if (part == SequencePart.SEGMENT) {
                // one slot stays free for VE (Galil's own vector example keeps it); _LMS is asked again only
                // when the slots counted since the last answer run out
                while (free < 2) {
                    free = (int) c.client().number("_LMS");
                    starved(s);
                    if (free < 2) {
                        follow();
                        Thread.sleep(pollMs);
                    }
                }
                free--;
                segments.add(s.origin());
                Sequence q = progress.program().sequenceAt(s.origin());
                end = q == null ? end : q.end();
            }
            if (part == SequencePart.VECTOR_END) {
                starved(s); // a fed sequence must still run when its VE comes
                vectorEnded = true;
            }
            c.require(gcnc.dmc.DmcPrinter.print(cmd));
            if (part == SequencePart.BEGIN) {
                progress.started();
                tripped = 0;
                feeding = !vectorEnded;
                vectorEnded = false;
            }
            if (!progress.hasStarted() || part != SequencePart.BEGIN) {
                progress.pointAt(s.origin());
            }
        }

        private void host(Sent s) throws IOException, RunFault, InterruptedException {
            Command cmd = s.command();
            switch (CommandKind.of(cmd)) {
                case AWAIT_SEQUENCE -> awaitSequence();
                case WAIT -> await(s, ((Command.Wait) cmd).milliseconds());
                case AFTER_VECTOR -> trip(s, ((Command.AfterVector) cmd).counts());
                case CALL -> call(s, ((Command.Call) cmd).label());
                // StreamRole.of, exhaustive over the commands, gives the host these four
                default -> throw new IllegalStateException("the host has no wait for " + cmd);
            }
        }

        /** {@code AMS}: until {@code _BGS} is 0, stopping a sequence that stalls. */
        private void awaitSequence() throws IOException, RunFault, InterruptedException {
            StallWatch stall = new StallWatch(stallSeconds);
            while (c.client().number("_BGS") != 0) {
                double[] at = follow();
                if (stall.stalled(at, !hold.held() && op.override() > 0)) {
                    c.stopAll();
                    throw stall.fault(progress.executingLine());
                }
                Thread.sleep(pollMs);
                between();
            }
            endedAtItsEnd();
        }

        /** {@code WT n}: n ms after the previous command was taken. */
        private void await(Sent s, long milliseconds) throws IOException, RunFault, InterruptedException {
            progress.pointAt(s.origin());
            long until = System.nanoTime() + milliseconds * 1_000_000L;
            while (System.nanoTime() < until) {
                between();
                Thread.sleep(Math.max(1, Math.min(pollMs, (until - System.nanoTime()) / 1_000_000L)));
            }
        }

        /** {@code AV n}: until {@code _AVS} reaches the sum of the sequence's AVs so far. */
        private void trip(Sent s, long counts) throws IOException, RunFault, InterruptedException {
            tripped += counts;
            while (c.client().number("_BGS") != 0 && c.client().number("_AVS") < tripped) {
                follow();
                Thread.sleep(pollMs);
                between();
            }
            starved(s); // a fed sequence that ran dry while the host waited: no output switches after it
        }

        /** {@code JS #L}: the wait for room, or the resident routine run with {@code XQ #L,0} until {@code _XQ0} is -1. */
        private void call(Sent s, String label) throws IOException, RunFault, InterruptedException {
            if (label.equals(StreamSplit.BUFFER_WAIT)) {
                // the program form's wait for room (JS #LMWAIT): the host polls _LMS itself, every pollMs,
                // until the next batch and VE fit (gclib's vector example reads _LMS every 100 ms)
                for (free = (int) c.client().number("_LMS"); free < StreamSplit.BUFFER_BATCH + 1;
                     free = (int) c.client().number("_LMS")) {
                    starved(s);
                    follow();
                    Thread.sleep(pollMs);
                    between();
                }
                starved(s);
                return;
            }
            c.require("XQ #" + label + ",0");
            progress.started();
            if (label.equals(gcnc.dmc.ProgramStop.LABEL)) {
                // a program stop: the resident routine waits for gstop=0 or the cycle start input
                progress.at(s.origin(), c.position(), op);
                ProgramStopWait.await(c, progress, op, s.origin(), pollMs, () -> c.executing() >= 0);
                between();
            }
            for (int xq = c.executing(); xq >= 0; xq = c.executing()) {
                progress.at(s.origin(), c.position(), op);
                Thread.sleep(pollMs);
                between();
            }
            if (c.errorCode() != 0) {
                RunFault f = c.refused("JS #" + label, progress.executingLine(), true);
                c.stopAll();
                throw f;
            }
        }

        /**
         * A sequence fed while it runs that has ended before its VE was sent: the buffer ran dry, and
         * the controller stopped the axes at the last segment's end (M13X8-74: "the controller will stop
         * motion instantly at the last vector"). Never taken for a normal end: E890 at its segment.
         */
        private void starved(Sent s) throws IOException, RunFault {
            if (!feeding || vectorEnded || c.client().number("_BGS") != 0) {
                return;
            }
            feeding = false;
            throw Starvation.fault(segments.stream().mapToInt(Integer::intValue).toArray(), c, progress, op);
        }

        /** One poll while a sequence runs: the segment executing names the block; the axes where they are. */
        private double[] follow() throws IOException {
            double[] at = c.position();
            int css = c.segment();
            int origin = segments.isEmpty() ? progress.executingIndex()
                    : segments.get(Download.Segments.segment(css, segments.size()));
            progress.at(origin, at, op);
            return at;
        }

        /** A sequence that ended away from its last segment's end was cut short (a limit switch, ST): the stop code says why. */
        private void endedAtItsEnd() throws IOException, RunFault {
            if (end == null || segments.isEmpty()) {
                return;
            }
            double[] at = c.position();
            if (Math.hypot(at[0] - end[0], at[1] - end[1]) <= tolerance) {
                progress.at(segments.get(segments.size() - 1), at, op);
                return;
            }
            // cut short: the segment it stopped in (_CSS keeps its count after the sequence ended) names the block
            int css = c.segment();
            progress.at(segments.get(Download.Segments.segment(css, segments.size())), at, op);
            int code = c.stopCode();
            c.stopAll();
            PositionText where = new PositionText(progress.program(), progress.blocks());
            throw new RunFault(Code.E825_NOT_READY, progress.executingLine(), true, "the sequence ended during line "
                    + progress.executingLine() + " with the axes at " + where.at(progress.executingLine(), at) + ", not at its end "
                    + where.at(progress.executingLine(), end) + " (stop code " + code + ": " + MachineLink.stopReason(code) + ")");
        }

        /**
         * What is checked between commands and polls: a fault routine of the resident program (#LIMSWI,
         * #POSERR, #AMPERR, a wait that timed out) that stopped the axes and the spindle, after which
         * nothing more is sent (the next segments would move on from where it stopped, the spindle off:
         * E825 with the controller's words); then the operator's stop, hold and override.
         */
        private void between() throws IOException, RunFault {
            java.util.Optional<gcnc.dmc.FaultMessage.Fault> fault = progress.controllerFault();
            if (fault.isPresent()) {
                c.stopAll();
                throw new RunFault(Code.E825_NOT_READY, progress.executingLine(), true, "its fault routine stopped it ('"
                        + fault.get() + "'): the axes and the spindle were stopped and nothing more is sent");
            }
            if (op.stopped()) {
                c.stopAll();
                throw new RunFault(Code.E828_STOPPED_BY_OPERATOR, progress.executingLine(), true, progress.executingLine());
            }
            hold.apply(c, progress, op);
        }
    }
}
