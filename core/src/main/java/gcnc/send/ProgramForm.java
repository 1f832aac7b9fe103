package gcnc.send;

import gcnc.diag.Code;
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
 */
public final class ProgramForm implements Form {
    private final int pollMs;
    private final double tolerance;
    private final double stallSeconds;

    /**
     * @param tolerance    how far (counts) the axes may end from the program's end point
     * @param stallSeconds how long the axes may stand still inside a vector sequence (no feed hold)
     *                     before the run is stopped as stalled
     */
    public ProgramForm(int pollMs, double tolerance, double stallSeconds) {
        this.pollMs = pollMs;
        this.tolerance = tolerance;
        this.stallSeconds = stallSeconds;
    }

    @Override
    public String name() {
        return "program";
    }

    @Override
    public void run(Piece piece, Controller c, Progress progress, Operator op, boolean step, boolean dryRun)
            throws RunFault, IOException, InterruptedException {
        if (!step) {
            send(piece, c, progress, op, dryRun);
            return;
        }
        for (Piece block : steps(piece, progress.program())) {
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
    private static int firstBlockLine(Piece p, DmcProgram program) {
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
    static List<Piece> steps(Piece piece, DmcProgram program) {
        List<Piece> out = new ArrayList<>();
        List<String> lines = piece.lines();
        int i = 0;
        while (i < lines.size()) {
            Piece.Builder b = new Piece.Builder();
            int first = piece.originOf(i);
            if (!lines.get(i).startsWith("#")) {
                b.add("#GCNC", first);
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
            if (j < lines.size() || !lines.subList(i, j).stream().anyMatch(l -> l.strip().equals("EN"))) {
                if (!lines.get(j - 1).strip().equals("EN")) {
                    b.add("EN", piece.originOf(j - 1));
                }
                // the program's routines (#NOHOME, #CMDERR ...: the labels after its EN) with every step,
                // since the header's and the blocks' jumps name them
                for (int k = routines(lines); k < lines.size(); k++) {
                    b.add(lines.get(k), piece.originOf(k));
                }
            }
            out.add(b.build());
            i = j;
        }
        return out;
    }

    /** The index of the first line after the program's first {@code EN} (its routines); the size when none. */
    private static int routines(List<String> lines) {
        for (int k = 0; k < lines.size(); k++) {
            if (lines.get(k).strip().equals("EN")) {
                return k + 1;
            }
        }
        return lines.size();
    }

    private void send(Piece piece, Controller c, Progress progress, Operator op, boolean dryRun)
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
    private static void compare(List<String> sent, List<String> back, Progress progress) throws RunFault {
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
    private void endedAtItsEnd(Piece piece, Controller c, Progress progress, Operator op) throws IOException, RunFault {
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
        progress.at(progress.executingIndex(), at, op);
        c.stopAll();
        throw new RunFault(Code.E825_NOT_READY, progress.executingLine(), true, "it ended during line "
                + progress.executingLine() + " with the axes at " + Resume.counts(at) + ", not at the end "
                + Resume.counts(last.end()) + " (stop code " + code + ": " + Controller.stopReason(code) + ")");
    }

    /** Polls until thread 0 ends, applying the operator's hold, override and stop between polls. */
    private void follow(Piece piece, Controller c, Progress progress, Operator op)
            throws RunFault, IOException, InterruptedException {
        boolean held = false;
        double ratio = 1;
        double[] still = null;
        long stillSince = 0;
        while (true) {
            if (op.stopped()) {
                c.stopAll();
                throw new RunFault(Code.E828_STOPPED_BY_OPERATOR, progress.executingLine(), true,
                        progress.executingLine());
            }
            if (op.held() != held) {
                held = op.held();
                ratio = held ? 0 : op.override();
                c.ratio(ratio);
                progress.events().accept(new Event.Hold(held, op.override()));
            } else if (!held && op.override() != ratio) {
                ratio = op.override();
                c.ratio(ratio);
                progress.events().accept(new Event.Hold(false, ratio));
            }
            int xq = c.executing();
            if (xq < 0) {
                int tc = c.errorCode();
                if (tc != 0) {
                    int ed = c.errorLine();
                    int origin = piece.originOf(ed);
                    progress.at(origin, null, op);
                    RunFault f = c.refused(origin >= 0 ? "'" + piece.lines().get(ed) + "'" : "the program", progress.executingLine(), true);
                    c.stopAll();
                    throw f;
                }
                endedAtItsEnd(piece, c, progress, op);
                return;
            }
            double[] at = c.position();
            progress.at(piece.originOf(xq), at, op);
            // a sequence that has begun and does not move (the profiler stopped taking segments): no
            // reply tells it, so the axes do; a hold, a dwell and a thread pass's wait for the spindle are not stalls
            Sequence s = progress.program().sequenceAt(piece.originOf(xq));
            boolean inMotion = s != null && !s.isThreadPass() && !held && op.override() > 0;
            if (!inMotion || still == null || Math.hypot(at[0] - still[0], at[1] - still[1]) > 1) {
                still = at;
                stillSince = System.nanoTime();
            } else if ((System.nanoTime() - stillSince) / 1e9 > stallSeconds) {
                c.stopAll();
                throw new RunFault(Code.E825_NOT_READY, progress.executingLine(), true, "the axes stood still for "
                        + Math.round(stallSeconds) + " s during line " + progress.executingLine()
                        + " while its motion had not ended (the controller stopped feeding the sequence)");
            }
            Thread.sleep(pollMs);
        }
    }
}
