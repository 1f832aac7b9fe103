package gcnc.send;

import gcnc.diag.Origin;
import gcnc.dmc.Command;
import gcnc.dmc.DmcReader;
import gcnc.dmc.Instruction;
import gcnc.dmc.Source;
import gcnc.machine.MachineProfile;
import gcnc.machine.Plane;
import gcnc.sim.Sequence;
import java.util.ArrayList;
import java.util.List;

/**
 * The compiled program the sender downloads: its instructions (the typed commands of gcnc.dmc,
 * each with its {@link Source}; a downloaded {@link Download} prints and packs them as FILE.dmc holds
 * them), the motions it makes ({@link Sequence}) with their places in
 * the plane and the DMC line of every segment, as the simulator ran them, and how long each line's
 * work takes, by the simulator's clock. Built from the
 * compiler's instructions as they come ({@link #of}), so that nothing reads DMC text back; a DMC
 * file with its map is read through {@link DmcReader}, the one reader of DMC text ({@link #read}).
 */
public final class DmcProgram {
    private final List<Instruction> instructions;
    private final List<Sequence> sequences;
    /** For each line, the index of the sequence it belongs to, or -1. */
    private final int[] sequenceOf;
    /** Seconds of the program's estimated time done when line i starts. */
    private final double[] secondsBefore;
    private final double totalSeconds;
    private final Plane plane;
    /** The characters of one controller line: what the downloaded pieces are packed to. */
    private final int lineWidth;

    private DmcProgram(List<Instruction> instructions, List<Sequence> sequences,
                       int[] sequenceOf, double[] secondsBefore, double totalSeconds, Plane plane, int lineWidth) {
        this.instructions = instructions;
        this.sequences = sequences;
        this.sequenceOf = sequenceOf;
        this.secondsBefore = secondsBefore;
        this.totalSeconds = totalSeconds;
        this.plane = plane;
        this.lineWidth = lineWidth;
    }

    /**
     * The simulator's cycle clock over a program's lines, as the compile replayed them
     * ({@link gcnc.CompileObserver#replayed}): the seconds before and after each line, and the cycle
     * time the simulation ended on ({@link gcnc.sim.SimReport#cycleSeconds}), which the run's time
     * left counts down to zero.
     */
    public record Clock(double[] beforeLine, double[] afterLine, double total) {
        double before(int i) {
            return i < beforeLine.length ? beforeLine[i] : total;
        }

        /**
         * The clock of {@code lines} replayed by themselves on {@code profile}'s machine (a DMC read back: no
         * compile ran); {@code sequences} receives the motions the replay ran.
         */
        static Clock replay(List<Instruction> lines, MachineProfile profile, List<Sequence> sequences) {
            double[] before = new double[lines.size()];
            double[] after = new double[lines.size()];
            gcnc.sim.Simulator sim = new gcnc.sim.Simulator(profile, gcnc.sim.SimOptions.defaults(),
                    new gcnc.diag.Diagnostics());
            sim.onReplayed(new gcnc.sim.Simulator.Replayed() {
                private int at;

                @Override
                public void line(Instruction line, double b, double a) {
                    before[at] = b;
                    after[at++] = a;
                }

                @Override
                public void sequence(Sequence s) {
                    sequences.add(s);
                }
            });
            sim.replay(lines);
            return new Clock(before, after, sim.report().cycleSeconds());
        }
    }

    /**
     * The program as the compiler handed it on, one instruction a line (what {@code Session.compile}
     * gives its consumer, in order), with the simulator's clock over those lines and the motions it
     * ran ({@link gcnc.CompileObserver#sequence}, in order): nothing of where they lie is read again here.
     *
     * @param profile the machine it was compiled for: the plane, and the controller's line width
     */
    public static DmcProgram of(List<Instruction> instructions, Clock clock, List<Sequence> sequences,
                                MachineProfile profile) {
        List<Instruction> all = List.copyOf(instructions);
        List<Sequence> motions = List.copyOf(sequences);
        int n = all.size();
        int[] owner = new int[n];
        java.util.Arrays.fill(owner, -1);
        for (int s = 0; s < motions.size(); s++) {
            java.util.Arrays.fill(owner, motions.get(s).first(), Math.min(n, motions.get(s).last() + 1), s);
        }
        // the work done when a line starts: the clock before it, and for a line of a sequence the clock
        // where its sequence starts (the progress adds how far along it the axes are)
        double[] before = new double[n];
        for (int i = 0; i < n; i++) {
            before[i] = clock.before(owner[i] < 0 ? i : motions.get(owner[i]).first());
        }
        return new DmcProgram(all, motions, owner, before, clock.total(), Plane.of(profile),
                profile.controllerLimits().lineWidth());
    }

    /**
     * A DMC file and its source map read back (a program compiled earlier, a test's own DMC): every
     * line split into its commands and each read through {@link DmcReader}; a command it cannot read
     * is an {@link IllegalArgumentException} naming it (gcnc writes none).
     *
     * @param lines the DMC's lines, packed or one command each
     * @param map   the source map read back ({@link MapReader})
     */
    public static DmcProgram read(List<String> lines, MapReader.Map map, MachineProfile profile) {
        List<Instruction> out = new ArrayList<>(lines.size());
        for (int i = 0; i < lines.size(); i++) {
            int at = i + 1;
            List<String> statements = DmcReader.statements(lines.get(i));
            if (statements.isEmpty()) {
                throw new IllegalArgumentException("DMC line " + at + " is empty");
            }
            for (int k = 0; k < statements.size(); k++) {
                String text = statements.get(k);
                Command c = DmcReader.read(text, (code, args) -> {
                    throw new IllegalArgumentException("DMC line " + at + " '" + text + "': " + code.id());
                });
                String file = map.file(at, k);
                out.add(new Instruction(c, new Source(file == null ? Origin.PROGRAM : Origin.file(file), map.line(at, k), -1)));
            }
        }
        List<Sequence> sequences = new ArrayList<>();
        Clock clock = Clock.replay(out, profile, sequences);
        return of(out, clock, sequences, profile);
    }

    /** The characters of one controller line, the model's: what a downloaded piece is packed to ({@link Download}). */
    public int lineWidth() {
        return lineWidth;
    }

    /** The instructions, in order (a downloaded piece prints and packs them: {@link Download#lines}). */
    public List<Instruction> instructions() {
        return instructions;
    }

    /** How many instructions. */
    public int size() {
        return instructions.size();
    }

    /** Whether the program waits with AV (a probe row the run then relies on: AV's distance, ProbeRow.AV_RELATIVE). */
    public boolean usesAfterVector() {
        for (Instruction i : instructions) {
            if (i.command() instanceof gcnc.dmc.Command.AfterVector) {
                return true;
            }
        }
        return false;
    }

    /** The command on line {@code index} (0-based), or null beyond the program. */
    public Command command(int index) {
        return index >= 0 && index < instructions.size() ? instructions.get(index).command() : null;
    }

    public Plane plane() {
        return plane;
    }

    /** The G-code line a program line (0-based) came from; 0 for the header and footer. */
    public int sourceLine(int index) {
        return index >= 0 && index < instructions.size() ? instructions.get(index).source().line() : 0;
    }

    /** The G-code file a program line came from when it is a called program's, else null. */
    public String sourceFile(int index) {
        return index >= 0 && index < instructions.size() ? instructions.get(index).source().file() : null;
    }

    public List<Sequence> sequences() {
        return sequences;
    }

    /** The sequence line {@code index} belongs to, or null. */
    public Sequence sequenceAt(int index) {
        int s = index >= 0 && index < sequenceOf.length ? sequenceOf[index] : -1;
        return s < 0 ? null : sequences.get(s);
    }

    /** Estimated seconds of work done before line {@code index} starts. */
    public double secondsBefore(int index) {
        return index <= 0 ? 0 : index >= secondsBefore.length ? totalSeconds : secondsBefore[index];
    }

    public double totalSeconds() {
        return totalSeconds;
    }

    /** The first program line of the run of lines that came from the G-code line of line {@code index}. */
    public int blockStart(int index) {
        int s = sourceLine(index);
        int i = index;
        while (i > 0 && sourceLine(i - 1) == s) {
            i--;
        }
        return i;
    }

    /**
     * The G-code line of the block before the one line {@code index} belongs to (the last block
     * completed when {@code index} is executing), or 0 when there is none.
     */
    public int blockBefore(int index) {
        for (int i = blockStart(index) - 1; i >= 0; i--) {
            if (sourceLine(i) > 0) {
                return sourceLine(i);
            }
        }
        return 0;
    }

    /**
     * One motion of a G-code block as the controller runs it: one segment ({@code VP}/{@code CR},
     * piece {@code from} = {@code to} of its sequence) or a thread pass whole ({@code 0, 0}). A block
     * makes one or several (an arc with its closing VP, a canned cycle's passes, G28's two legs); in
     * a blended sequence they stand among the other blocks' segments (docs/run.md, "Resume").
     */
    public record Motion(Sequence sequence, int from, int to) {
        /** Galil coordinates where the motion starts. */
        public double[] start() {
            return sequence.isThreadPass() || from == 0 ? sequence.start() : sequence.pieces().get(from).from();
        }

        /** Galil coordinates where it ends. */
        public double[] end() {
            return sequence.isThreadPass() || to == sequence.pieces().size() - 1 ? sequence.end()
                    : sequence.pieces().get(to).to();
        }
    }

    /** The motions of G-code line {@code line}, in program order. */
    public List<Motion> motionsOf(int line) {
        List<Motion> out = new ArrayList<>();
        for (Sequence s : sequences) {
            if (s.isThreadPass()) {
                if (sourceLine(s.first()) == line) {
                    out.add(new Motion(s, 0, 0));
                }
                continue;
            }
            for (int k = 0; k < s.pieces().size(); k++) {
                if (sourceLine(s.pieces().get(k).line()) == line) {
                    out.add(new Motion(s, k, k));
                }
            }
        }
        return out;
    }

    /** The program lines (0-based) of the sequences whose first line came from G-code line {@code line}, in order. */
    public List<Sequence> sequencesOf(int line) {
        List<Sequence> out = new ArrayList<>();
        for (Sequence s : sequences) {
            if (sourceLine(s.first()) == line) {
                out.add(s);
            }
        }
        return out;
    }

    /** The first program line that came from G-code line {@code line}, or -1. */
    public int firstLineOf(int line) {
        for (int i = 0; i < instructions.size(); i++) {
            if (sourceLine(i) == line) {
                return i;
            }
        }
        return -1;
    }

    /** The labels the program declares ({@code #NAME}). */
    public int labels() {
        int n = 0;
        for (Instruction i : instructions) {
            if (i.command() instanceof Command.Label) {
                n++;
            }
        }
        return n;
    }

    /** The variables the program assigns ({@code TOOL}, {@code gline}, {@code gsp}, a thread's phase errors, a deadline's), sorted. */
    public List<String> variables() {
        java.util.Set<String> names = new java.util.TreeSet<>();
        for (Instruction i : instructions) {
            String name = assigned(i.command());
            if (name != null) {
                names.add(name);
            }
        }
        return List.copyOf(names);
    }

    /** The variable {@code c} assigns, or null: each command is decided, so that the preflight counts a new one's. */
    private static String assigned(Command c) {
        return switch (gcnc.dmc.CommandKind.of(c)) {
            case TOOL_NUMBER -> "TOOL";
            case SET_VARIABLE -> ((Command.SetVariable) c).name();
            case SET_DEADLINE -> ((Command.SetDeadline) c).name();
            case SYNC_POINT -> ((Command.SyncPoint) c).variable();
            case PHASE_ERROR -> ((Command.PhaseError) c).variable();
            case LABEL, SERVO_HERE, VECTOR_MODE, VECTOR_ACCELERATION, VECTOR_DECELERATION, STOCK, FEED_MARK,
                    SOURCE_MARK, REMARK, VECTOR_SPEED, VECTOR_POSITION, CIRCULAR_ARC, VECTOR_END, BEGIN_SEQUENCE,
                    AWAIT_SEQUENCE, AFTER_VECTOR, OFFSET, WAIT, REVOLVER, PASS_THROUGH_M, OUTPUT, GEAR_MASTER,
                    WAIT_PAST, GEAR_RATIO, INCREMENT_POSITION, DEFINE_POSITION, POSITION_ABSOLUTE, BEGIN, AFTER_MOTION, END,
                    ANALOG_OUT, AXIS_SETTING, SOFT_LIMIT, JUMP, CALL, MESSAGE, STOP, ABORT, CLEAR_STACK -> null;
        };
    }

    /**
     * The most segments one sequence puts in the vector buffer before its {@code BGS}: all of it, or
     * the first fill of one fed while it runs (BGS before VE, docs/galil.md "Continuous contouring").
     */
    public int mostSegments() {
        int m = 0;
        for (Sequence s : sequences) {
            int bgs = s.last();
            for (int i = s.first(); i <= s.last(); i++) {
                if (instructions.get(i).command() instanceof Command.BeginSequence) {
                    bgs = i;
                    break;
                }
            }
            int before = 0;
            for (Sequence.Piece p : s.pieces()) {
                before += p.line() < bgs ? 1 : 0;
            }
            m = Math.max(m, before);
        }
        return m;
    }

    /**
     * Whether compiled line {@code index} belongs to the program stop's wait routine ({@code #PSTOP}
     * to its {@code EN}): thread 0 standing there waits for the operator.
     */
    public boolean inProgramStop(int index) {
        if (stopRoutine == null) {
            // the routine's label, then the first EN after it
            int from = -1;
            for (int i = 0; i < size() && from < 0; i++) {
                if (command(i) instanceof Command.Label l && l.name().equals(gcnc.dmc.ProgramStop.LABEL)) {
                    from = i;
                }
            }
            int to = -1;
            for (int i = from + 1; from >= 0 && i < size() && to < 0; i++) {
                if (command(i) instanceof Command.End) {
                    to = i;
                }
            }
            stopRoutine = new int[] {from, to};
        }
        return index >= 0 && stopRoutine[0] >= 0 && index >= stopRoutine[0] && index <= stopRoutine[1];
    }

    /** The first program stop's call ({@code JS #PSTOP}) at or after compiled line {@code from}, or -1. */
    public int programStopFrom(int from) {
        for (int i = Math.max(0, from); i < size(); i++) {
            if (command(i) instanceof Command.Call c && c.label().equals(gcnc.dmc.ProgramStop.LABEL)) {
                return i;
            }
        }
        return -1;
    }

    private int[] stopRoutine;

    /** Is {@code c} a segment of a vector sequence ({@code VP}, {@code CR})? */
    public static boolean isSegment(Command c) {
        return gcnc.dmc.SequencePart.of(c) == gcnc.dmc.SequencePart.SEGMENT;
    }
}
