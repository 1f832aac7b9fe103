package gcnc.dmc;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * The stream form of a program (docs/galil.md, "The stream form"), made from the instructions of
 * its program form as they come: the set-up before the first block, the error handlers and wait
 * routines after {@code EN}, and every block that must run inside the controller (one that holds a
 * command of role {@link StreamRole#EMBED}: a thread's encoder waits) make the <em>resident</em>
 * program, downloaded once; everything else is the <em>segment stream</em>, handed to
 * {@code stream} in order as it comes. A moved block becomes the routine {@code #B<n>} and the
 * stream calls it ({@code JS #B<n>}, which the host runs as {@code XQ #B<n>,0}).
 *
 * <p>The resident program is the program form's header with {@code gready=0} after its label and
 * {@code gready=1} at its end, so that a host that ran it ({@code XQ #GCNC,0}) can tell a set-up
 * that finished from one that stopped (the homing check); then {@code EN}, the moved blocks, and the
 * program form's routines.
 *
 * <p>The resident program's lines are counted packed ({@link LinePacker}), as it is written.
 *
 * <p>Look-ahead: the commands of one block, at most {@link #RUN_LIMIT}; the resident program is held
 * until the end, at most {@code residentCap} packed lines (beyond that only counted: it cannot be
 * downloaded anyway).
 */
public final class StreamSplit implements Consumer<Instruction> {
    /** The variable the resident set-up sets to 1 when it ran to its end. */
    public static final String READY = "gready";
    /**
     * The routine a sequence longer than the buffer waits in for room ({@code JS #LMWAIT}: back to
     * itself while {@code _LMS} is below the next batch and VE); in the stream the host polls
     * {@code _LMS} instead (docs/galil.md, "Continuous contouring").
     */
    public static final String BUFFER_WAIT = "LMWAIT";
    /** The segments given after each wait for room. */
    public static final int BUFFER_BATCH = 100;
    /**
     * How many segments inside the buffer a trip point's segment is before its {@code AV} is written
     * in a sequence fed while it runs (at a wait for room, or after {@code VE}): the compile's and a
     * resume's rule alike (docs/galil.md, "Continuous contouring").
     */
    public static final int TRIP_LEAD = BUFFER_BATCH;
    /** The most commands of one block held back to see whether the block must be moved. */
    public static final int RUN_LIMIT = 4096;
    /** The moved blocks' labels: {@code #B1}, {@code #B2} ... */
    public static final String ROUTINE = "B";

    /** What the split found once the program ended. */
    public record Result(List<Instruction> resident, long residentLines, int residentLabels, long streamLines,
                         int moved, List<Source> tooLong) {
        /** Whether the resident program was held whole (not only counted). */
        public boolean held() {
            return !resident.isEmpty();
        }
    }

    private enum Phase { HEADER, BODY, FOOTER }

    private final Consumer<Instruction> stream;
    private final long residentCap;
    private Phase phase = Phase.HEADER;
    private final List<Instruction> header = new ArrayList<>();
    private final List<Instruction> routines = new ArrayList<>();
    private final List<Instruction> footer = new ArrayList<>();
    /** The commands of the block being read, not yet handed on. */
    private final List<Instruction> run = new ArrayList<>();
    private Source runSource;
    private boolean runEmbeds;
    /** Commands of the block being read already went to the stream (it passed {@link #RUN_LIMIT}). */
    private boolean runStreamed;
    private final int width;
    /** Counts the moved blocks' routines as packed lines. */
    private final LinePacker routineCounter;
    private long routineLines;
    private boolean routinesWhole = true;
    private int routineLabels;
    private long streamLines;
    private final List<Source> tooLong = new ArrayList<>();

    /**
     * @param stream      receives the segment stream, in order
     * @param residentCap the most resident lines held (the model's program memory); beyond it they are counted
     * @param width       the characters of a program line (the model's), to count the resident program's lines packed
     */
    public StreamSplit(Consumer<Instruction> stream, long residentCap, int width) {
        this.stream = stream;
        this.residentCap = residentCap;
        this.width = width;
        this.routineCounter = new LinePacker(width, l -> routineLines++);
    }

    @Override
    public void accept(Instruction i) {
        boolean end = i.command() instanceof Command.End;
        if (phase == Phase.HEADER) {
            if (!end && i.source().line() <= 0) {
                header.add(i);
                return;
            }
            phase = Phase.BODY;
        }
        if (phase == Phase.BODY) {
            if (end) {
                // the program's EN: the routines follow
                flush();
                phase = Phase.FOOTER;
            } else {
                body(i);
                return;
            }
        }
        footer.add(i);
    }

    private void body(Instruction i) {
        if (!run.isEmpty() && !sameBlock(runSource, i.source())) {
            flush();
        }
        if (run.isEmpty() && !sameBlock(runSource, i.source())) {
            runSource = i.source();
            runStreamed = false;
        }
        run.add(i);
        if (role(i.command()) == StreamRole.EMBED) {
            if (!runEmbeds && runStreamed) {
                tooLong(runSource); // the block's first commands went to the stream already
            }
            runEmbeds = true;
        }
        if (run.size() >= RUN_LIMIT) {
            if (runEmbeds) {
                tooLong(runSource);
                run.clear();
                runEmbeds = false;
            } else {
                flush();
            }
            runStreamed = true;
        }
    }

    /**
     * The command's {@link StreamRole}, remembered per kind of command: every role is its command
     * kind's (StreamRole's visitor answers each kind with a constant), and a kind's answer looked up
     * in a small map costs less than a visit per instruction (three million for a million blocks).
     */
    private StreamRole role(Command c) {
        Class<?> kind = c.getClass();
        StreamRole r = roles.get(kind);
        if (r == null) {
            r = StreamRole.of(c);
            roles.put(kind, r);
        }
        return r;
    }

    private final java.util.Map<Class<?>, StreamRole> roles = new java.util.IdentityHashMap<>();

    private void tooLong(Source s) {
        if (!tooLong.contains(s)) {
            tooLong.add(s);
        }
    }

    /** One block run of the G-code: the same file, line and pass. */
    private static boolean sameBlock(Source a, Source b) {
        // the same Origin object in nearly every case: compared by identity first (a record's equals goes
        // through ObjectMethods' method handles, 5 % of a 1,000,000-block compile's profile, issue 35)
        return a != null && a.line() == b.line() && a.block() == b.block()
                && (a.origin() == b.origin() || a.origin().equals(b.origin()));
    }

    /** The block read so far: into a routine of the resident program if it must run there, else to the stream. */
    private void flush() {
        if (run.isEmpty()) {
            return;
        }
        if (runEmbeds && !tooLong.contains(runSource)) {
            String label = ROUTINE + (routineLabels + 1);
            Source at = run.get(0).source();
            keep(new Instruction(new Command.Label(label), at));
            run.forEach(this::keep);
            keep(new Instruction(new Command.End(), run.get(run.size() - 1).source()));
            routineLabels++;
            send(new Instruction(new Command.Call(label), at));
        } else if (!runEmbeds) {
            for (int k = 0; k < run.size(); k++) { // (a loop, not forEach: no lambda per block)
                send(run.get(k));
            }
        }
        run.clear();
        runEmbeds = false;
    }

    private void keep(Instruction i) {
        routineCounter.accept(i);
        if (routinesWhole && routineLines < residentCap) {
            routines.add(i);
        } else {
            routinesWhole = false;
        }
    }

    private void send(Instruction i) {
        streamLines++;
        stream.accept(i);
    }

    /** The resident program and the counts, once the program form's last instruction has passed. */
    public Result finish() {
        flush();
        List<Instruction> resident = new ArrayList<>();
        if (!header.isEmpty()) {
            resident.add(header.get(0)); // #GCNC
            resident.add(new Instruction(new Command.SetVariable(READY, 0), Source.NONE));
            resident.addAll(header.subList(1, header.size()));
        }
        resident.add(new Instruction(new Command.SetVariable(READY, 1), Source.NONE));
        resident.add(new Instruction(new Command.End(), Source.NONE));
        routineCounter.flush();
        // the set-up ends with EN and each routine and handler starts with its label: the three parts pack apart
        long lines = LinePacker.count(resident, width) + routineLines;
        resident.addAll(routines);
        // the program form's own EN is replaced by the one above
        List<Instruction> handlers = footer.isEmpty() ? footer : footer.subList(1, footer.size());
        lines += LinePacker.count(handlers, width);
        resident.addAll(handlers);
        boolean whole = routinesWhole;
        int labels = routineLabels;
        for (Instruction i : header) {
            labels += i.command() instanceof Command.Label ? 1 : 0;
        }
        for (Instruction i : footer) {
            labels += i.command() instanceof Command.Label ? 1 : 0;
        }
        return new Result(whole ? resident : List.of(), lines, labels, streamLines, routineLabels, List.copyOf(tooLong));
    }
}
