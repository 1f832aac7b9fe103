package gcnc.send;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import gcnc.dmc.StreamRole;
import gcnc.dmc.StreamSplit;
import gcnc.sim.Sequence;
import java.io.IOException;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

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
 * resume (a piece that starts at the resume point) is streamed the same way.
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

    /** A command of the run and the compiled program's line it stands for. */
    private record Sent(Command command, int origin) {
    }

    /** The piece as the two parts of the stream form, each command with its compiled line. */
    record Split(List<Sent> resident, List<Sent> stream) {
        /** The resident program as it is downloaded: packed into lines as the compile writes it. */
        List<String> residentLines(int width) {
            return Download.packedLines(resident.stream().map(Sent::command).toList(), width);
        }
    }

    /** The piece pre-flight counted and the run sends: split once for both. */
    private Download splitPiece;
    private Split splitOfPiece;

    private Split splitOnce(Download piece, DmcProgram program) {
        if (piece != splitPiece) {
            splitOfPiece = split(piece, program);
            splitPiece = piece;
        }
        return splitOfPiece;
    }

    /** {@code piece} split as the compile splits a program ({@link StreamSplit}), each command keeping its compiled line. */
    static Split split(Download piece, DmcProgram program) {
        Map<Instruction, Integer> origins = new IdentityHashMap<>();
        List<Instruction> stream = new ArrayList<>();
        StreamSplit split = new StreamSplit(stream::add, Long.MAX_VALUE, program.lineWidth());
        for (int j = 0; j < piece.commands().size(); j++) {
            int o = Math.max(0, piece.originOf(j));
            Instruction i = new Instruction(piece.commands().get(j), program.instructions().get(o).source());
            origins.put(i, o);
            split.accept(i);
        }
        List<Instruction> resident = split.finish().resident();
        // a command the split made (gready, a routine's label and EN, the call of a moved block) stands
        // for the compiled line of the command beside it
        List<Sent> r = new ArrayList<>();
        Map<String, Integer> routineStart = new java.util.HashMap<>();
        int last = 0;
        String label = null;
        for (int k = 0; k < resident.size(); k++) {
            Instruction i = resident.get(k);
            Integer o = origins.get(i);
            if (i.command() instanceof Command.Label l) {
                label = l.name();
                Integer next = k + 1 < resident.size() ? origins.get(resident.get(k + 1)) : null;
                if (next != null) {
                    routineStart.put(label, next);
                }
            }
            last = o != null ? o : last;
            r.add(new Sent(i.command(), o != null ? o : last));
        }
        List<Sent> s = new ArrayList<>(stream.size());
        last = 0;
        for (Instruction i : stream) {
            Integer o = origins.get(i);
            if (o == null && i.command() instanceof Command.Call call) {
                o = routineStart.get(call.label());
            }
            last = o != null ? o : last;
            s.add(new Sent(i.command(), last));
        }
        return new Split(r, s);
    }

    @Override
    public void run(Download piece, MachineLink c, Progress progress, Operator op, boolean step, boolean dryRun)
            throws RunFault, IOException, InterruptedException {
        Split split = splitOnce(piece, progress.program());
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
            operator();
            switch (StreamRole.of(cmd)) {
                case SEND -> send(s);
                case HOST -> host(s);
                case EMBED -> throw new IllegalStateException("the split leaves no embedded command in the stream: " + cmd);
            }
        }

        private void send(Sent s) throws IOException, RunFault, InterruptedException {
            Command cmd = s.command();
            if (cmd instanceof Command.VectorSpeed) {
                segments.clear();
            }
            if (DmcProgram.isSegment(cmd)) {
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
            if (cmd instanceof Command.VectorEnd) {
                starved(s); // a fed sequence must still run when its VE comes
                vectorEnded = true;
            }
            c.require(gcnc.dmc.DmcPrinter.print(cmd));
            if (cmd instanceof Command.BeginSequence) {
                progress.started();
                tripped = 0;
                feeding = !vectorEnded;
                vectorEnded = false;
            }
            if (!progress.hasStarted() || !(cmd instanceof Command.BeginSequence)) {
                progress.pointAt(s.origin());
            }
        }

        private void host(Sent s) throws IOException, RunFault, InterruptedException {
            Command cmd = s.command();
            if (cmd instanceof Command.AwaitSequence) {
                StallWatch stall = new StallWatch(stallSeconds);
                while (c.client().number("_BGS") != 0) {
                    double[] at = follow();
                    if (stall.stalled(at, !hold.held() && op.override() > 0)) {
                        c.stopAll();
                        throw stall.fault(progress.executingLine());
                    }
                    Thread.sleep(pollMs);
                    operator();
                }
                endedAtItsEnd();
            } else if (cmd instanceof Command.Wait w) {
                progress.pointAt(s.origin());
                long until = System.nanoTime() + w.milliseconds() * 1_000_000L;
                while (System.nanoTime() < until) {
                    operator();
                    Thread.sleep(Math.max(1, Math.min(pollMs, (until - System.nanoTime()) / 1_000_000L)));
                }
            } else if (cmd instanceof Command.AfterVector av) {
                tripped += av.counts();
                while (c.client().number("_BGS") != 0 && c.client().number("_AVS") < tripped) {
                    follow();
                    Thread.sleep(pollMs);
                    operator();
                }
                starved(s); // a fed sequence that ran dry while the host waited: no output switches after it
            } else if (cmd instanceof Command.Call call && call.label().equals(StreamSplit.BUFFER_WAIT)) {
                // the program form's wait for room (JS #LMWAIT): the host polls _LMS itself, every pollMs,
                // until the next batch and VE fit (gclib's vector example reads _LMS every 100 ms)
                for (free = (int) c.client().number("_LMS"); free < StreamSplit.BUFFER_BATCH + 1;
                     free = (int) c.client().number("_LMS")) {
                    starved(s);
                    follow();
                    Thread.sleep(pollMs);
                    operator();
                }
                starved(s);
            } else if (cmd instanceof Command.Call call) {
                c.require("XQ #" + call.label() + ",0");
                progress.started();
                if (call.label().equals(gcnc.dmc.ProgramStop.LABEL)) {
                    // a program stop: the resident routine waits for gstop=0 or the cycle start input
                    progress.at(s.origin(), c.position(), op);
                    ProgramStopWait.await(c, progress, op, s.origin(), pollMs, () -> c.executing() >= 0);
                    operator();
                }
                for (int xq = c.executing(); xq >= 0; xq = c.executing()) {
                    progress.at(s.origin(), c.position(), op);
                    Thread.sleep(pollMs);
                    operator();
                }
                if (c.errorCode() != 0) {
                    RunFault f = c.refused("JS #" + call.label(), progress.executingLine(), true);
                    c.stopAll();
                    throw f;
                }
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
            double[] at = c.position();
            int css = c.segment(); // the last segment executed (SegmentCount: one place for _CSS's base)
            int k = Math.max(1, Math.min(segments.size(), css));
            progress.at(segments.get(k - 1), at, op);
            int code = c.stopCode();
            feeding = false;
            c.stopAll();
            throw new RunFault(Code.E890_BUFFER_STARVED, progress.executingLine(), true, k, progress.executingLine(),
                    code == 101 ? "" : " (stop code " + code + ": " + MachineLink.stopReason(code) + ")");
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

        /** The operator's stop, hold and override, between commands and polls. */
        private void operator() throws IOException, RunFault {
            if (op.stopped()) {
                c.stopAll();
                throw new RunFault(Code.E828_STOPPED_BY_OPERATOR, progress.executingLine(), true, progress.executingLine());
            }
            hold.apply(c, progress, op);
        }
    }
}
