package gcnc.controller;

import java.io.Writer;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * The state of one virtual Galil: program memory, variables and arrays, the eight program threads, the
 * vector motion, the spindle encoder with the gearing and settling moves of a thread pass ({@link Gearing}), the digital outputs and the spindle's analog offsets, the last error. Every entry point is
 * synchronized on the controller: the connections' commands and the clock's {@link #advance} never
 * interleave, so a run is a function of the commands and of how far the clock went, and a test that
 * drives {@link #advance} itself gets the same run every time.
 *
 * <p>{@link Statements} executes a command, from the host or from a thread; this class holds what the
 * commands act on and answers the operands ({@code _LMS}, {@code _CSS}, ...: {@link Operands}) for them.
 */
public final class VirtualGalil implements Expressions.Scope {
    /** Where the controller's unsolicited output (a program's MG, a program error) goes. */
    public interface Listener {
        void unsolicited(byte[] bytes);

        /** The port the link is: 'S' the main serial port (the pty, and a test's own listener), 'A'..'H' an Ethernet handle. */
        default char port() {
            return 'S';
        }
    }

    /** Host commands waiting for the controller's lock: the clock lets them in first ({@link #letCommandsIn}). */
    private final java.util.concurrent.atomic.AtomicInteger asking = new java.util.concurrent.atomic.AtomicInteger();

    final Model model;
    final ProgramMemory program = new ProgramMemory();
    final Map<String, Double> variables = new HashMap<>();
    final Map<String, double[]> arrays = new HashMap<>();
    final ProgramThread[] threads = new ProgramThread[8];
    final VectorMotion motion;
    /** The spindle encoder, gearing to it and independent moves: a thread pass. */
    final Gearing gearing;
    final boolean[] servo;
    final double[] offsets;
    /**
     * IT of each axis, 1 at power-up ("1 means no filtering", command reference IT). Recorded and read back
     * ({@code _ITa}); a value below 1 is not modelled (the motion runs unfiltered) and the trace says so.
     */
    final double[] smoothing;
    long outputs;
    /** Inputs read 1 when nothing pulls them low (Galil's inputs are pulled up). */
    long inputs = -1L;
    Tc lastError = Tc.NONE;
    int errorLine = -1;
    int errorThread = -1;
    /** CW: 1 marks unsolicited characters with their high bit set, 2 does not (the power-up value). */
    int cw = 2;
    /** CF: the port unsolicited messages go to, 'S' (the main serial port) at power-up (COMALL CF, default S). */
    char cf = 'S';
    /** EO: whether the serial port echoes what it receives; the model's power-up value (galil_models.csv serial_echo). */
    volatile boolean echo;
    /** The port the host command being executed came in on (for CF I, EO, WH); 0 inside a thread. */
    char port;
    /** The Ethernet handles in use (COMALL TH: A-H). */
    private final boolean[] handles = new boolean[8];
    boolean limitTripped;
    private double time;
    /** How many statements each thread runs in a step (20 a millisecond, or a slow-thread fault's). */
    private final DecodeRate decode;
    private final SegmentTrace trace;
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    final Statements statements;
    /** Where within 2 samples each MF/MR trip is seen (ThreadWaits.past); seeded, so a run repeats. */
    final java.util.Random tripPhase;

    /** The spindle drive and encoder of the haas profile: 410 r/min a volt, 4,096 counts a revolution. */
    public static final double SPINDLE_RATE = 410 * 4096 / 60.0;

    /** A controller of {@code model} with the segment faults of {@code faults} armed, tracing to {@code trace} (or null). */
    public VirtualGalil(Model model, List<InjectedFault> faults, Writer trace) {
        this(model, faults, trace, SPINDLE_RATE);
    }

    /**
     * As above, wired to a spindle whose encoder turns {@code spindleRate} counts a second per volt
     * of its channel's {@code OF} (the lathe's drive and encoder: r/min per volt × counts per rev / 60).
     */
    public VirtualGalil(Model model, List<InjectedFault> faults, Writer trace, double spindleRate) {
        this(model, faults, trace, spindleRate, TRIP_SEED);
    }

    /** The seed of the trip phase ({@link #tripPhase}) unless a test gives its own. */
    public static final long TRIP_SEED = 30;

    /**
     * As above, with MF/MR trips seen at the trip phase seeded by {@code tripSeed}: 0, 1 or 2 servo
     * samples after the first sample past the count (COMALL MF: accurate to the counts in 2*TM).
     */
    public VirtualGalil(Model model, List<InjectedFault> faults, Writer trace, double spindleRate, long tripSeed) {
        this.tripPhase = new java.util.Random(tripSeed);
        this.model = model;
        this.trace = trace == null ? null : new SegmentTrace(trace);
        this.servo = new boolean[model.axes];
        this.offsets = new double[model.axes];
        this.smoothing = new double[model.axes];
        java.util.Arrays.fill(smoothing, 1);
        this.echo = model.galil.serialEcho();
        for (int i = 0; i < threads.length; i++) {
            threads[i] = new ProgramThread(i);
        }
        MotionEvents events = new MotionEvents(this, this.trace);
        this.motion = new VectorMotion(model.galil, events);
        this.gearing = new Gearing(model.axes, motion.position, servo, offsets, spindleRate, events);
        motion.arm(faults);
        this.decode = new DecodeRate(faults);
        this.statements = new Statements(this);
        if (this.trace != null) {
            this.trace.header(model.revision);
        }
    }

    /** An event of the trace at time {@code t}. */
    void event(String text, double t) {
        if (trace != null) {
            trace.event(text, t);
        }
    }

    /** An event of the trace at the controller's time now (an AV's trip: docs/virtual-controller.md, "Trace"). */
    void traceEvent(String text) {
        event(text, time);
    }

    public void addListener(Listener l) {
        listeners.add(l);
    }

    public void removeListener(Listener l) {
        listeners.remove(l);
    }

    /** Controller time, seconds since power-up. */
    public synchronized double time() {
        return time;
    }

    /**
     * Executes one command from the host (a statement without its terminator) and returns what the
     * controller sends before its {@code :} ("" for a command without data, "data\r\n" for an
     * interrogation); a rejected command throws, sets the error {@code TC1} reports, and changes nothing.
     */
    String command(String statement, char from) throws GalilException {
        asking.incrementAndGet();
        try {
            return answer(statement, from);
        } finally {
            asking.decrementAndGet();
        }
    }

    private synchronized String answer(String statement, char from) throws GalilException {
        port = from;
        try {
            return statements.execute(statement, null);
        } catch (GalilException e) {
            lastError = e.tc;
            throw e;
        } finally {
            port = 0;
        }
    }

    /** A command from the main serial port (a test driving the controller without a link). */
    synchronized String command(String statement) throws GalilException {
        return command(statement, 'S');
    }

    /** A free Ethernet handle for a new TCP connection, 'A'..'H', or 0 when all eight are taken. */
    synchronized char openHandle() {
        for (int i = 0; i < handles.length; i++) {
            if (!handles[i]) {
                handles[i] = true;
                return (char) ('A' + i);
            }
        }
        return 0;
    }

    synchronized void closeHandle(char h) {
        if (h >= 'A' && h <= 'H') {
            handles[h - 'A'] = false;
        }
    }

    /** Whether the serial port echoes now (EO). */
    boolean echoes() {
        return echo;
    }

    /** A {@code reject} fault answered {@code ?}: TC1 says the command was not recognized. */
    synchronized void rejected() {
        lastError = Tc.UNRECOGNIZED;
    }

    /** Checks that a DL may start now (not while a thread runs: TC 17). */
    synchronized void downloadAllowed(String args) throws GalilException {
        try {
            for (ProgramThread t : threads) {
                if (t.running()) {
                    throw new GalilException(Tc.DL_WHILE_RUNNING);
                }
            }
            if (!args.isEmpty() && !args.equals("#")) {
                throw new GalilException(Tc.OPERAND);
            }
        } catch (GalilException e) {
            lastError = e.tc;
            throw e;
        }
    }

    /** Stores a downloaded program ({@code append} for {@code DL #}). */
    synchronized void download(String text, boolean append) throws GalilException {
        try {
            program.download(text, append, model);
        } catch (GalilException e) {
            lastError = e.tc;
            throw e;
        }
    }

    /**
     * Lets a waiting host command in before the clock's next slice, waiting at most 50 ms of real time:
     * a Galil answers its host while its motion runs, but a Java monitor is not fair, and a clock that
     * takes the lock back at once could keep a command out for seconds on a busy machine (a poll then
     * timed out, E822, with the controller idle at the program's end).
     */
    void letCommandsIn() {
        long until = System.nanoTime() + 50_000_000L;
        while (asking.get() > 0 && System.nanoTime() < until) {
            java.util.concurrent.locks.LockSupport.parkNanos(100_000L);
        }
    }

    /** Runs {@code seconds} of controller time: the motion, then every running thread, a millisecond at a time. */
    public synchronized void advance(double seconds) {
        double left = seconds;
        while (left > 1e-12) {
            double h = Math.min(left, VectorMotion.STEP);
            motion.advance(h, time);
            gearing.advance(h, time, motion.axis1, motion.axis2);
            time += h;
            left -= h;
            int budget = decode.statements(h);
            for (ProgramThread t : threads) {
                if (t.running()) {
                    statements.flow.run(t, budget);
                }
            }
        }
    }

    /** Runs until no thread runs and no motion moves, or {@code limit} seconds passed; the time it took. */
    public synchronized double settle(double limit) {
        double start = time;
        while (time - start < limit && (motion.running() || gearing.anyMoving() || anyThread())) {
            advance(VectorMotion.STEP);
        }
        return time - start;
    }

    private boolean anyThread() {
        for (ProgramThread t : threads) {
            if (t.running()) {
                return true;
            }
        }
        return false;
    }

    /**
     * Sends unsolicited text (a program's MG, a program's error) to the CF port only (COMALL MG: "The CF
     * command sets the default communication port for routing unsolicited messages"): every character's
     * high bit set after {@code CW 1}. With CF at a port no link holds, the text is lost, as on a Galil
     * whose serial port has nothing connected.
     */
    void unsolicited(String text) {
        byte[] b = text.getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);
        if (cw == 1) {
            for (int i = 0; i < b.length; i++) {
                b[i] = (byte) (b[i] | 0x80);
            }
        }
        for (Listener l : listeners) {
            if (l.port() == cf) {
                l.unsolicited(b);
            }
        }
    }

    /** Sets variable {@code name}; a new one when the model's variables are all taken is refused. */
    void assign(String name, double v) throws GalilException {
        if (!variables.containsKey(name) && variables.size() >= model.variables) {
            throw new GalilException(Tc.TOO_MANY_VARIABLES);
        }
        variables.put(name, v);
    }

    /** Sets digital output {@code n} (from 1) on or off ({@code SB}, {@code CB}, {@code OB}). */
    void setOutput(int n, boolean on) {
        outputs = on ? outputs | 1L << (n - 1) : outputs & ~(1L << (n - 1));
    }

    /** A statement of a thread failed: #CMDERR takes the thread over, or every thread stops (Galil's rule). */
    void programError(ProgramThread t, int line, String statement, GalilException e) {
        lastError = e.tc;
        errorLine = line;
        errorThread = t.number;
        int handler = program.label("CMDERR");
        if (handler >= 0 && !t.inErrorHandler) {
            t.start(handler);
            t.inErrorHandler = true;
            return;
        }
        for (ProgramThread each : threads) {
            each.halt();
        }
        unsolicited("?" + line + " " + statement + "\r\n");
    }

    // ---- operands and names (Expressions.Scope) ----

    /** A-H, or X Y Z W for A-D; -1 when not an axis of this model. */
    int axis(char c) {
        int a = switch (c) {
            case 'X' -> 0;
            case 'Y' -> 1;
            case 'Z' -> 2;
            case 'W' -> 3;
            default -> c >= 'A' && c <= 'H' ? c - 'A' : -1;
        };
        return a < model.axes ? a : -1;
    }

    /** The axes a string of letters names ("XY", "AB"), in order; TC 4 for anything else. */
    List<Integer> axes(String letters) throws GalilException {
        List<Integer> out = new ArrayList<>();
        for (char c : letters.toCharArray()) {
            int a = axis(c);
            if (a < 0 || out.contains(a)) {
                throw new GalilException(Tc.OPERAND);
            }
            out.add(a);
        }
        return out;
    }

    @Override
    public double variable(String name) throws GalilException {
        if (name.equals("TIME")) {
            return Math.floor(time * 1024);
        }
        Double v = variables.get(name);
        if (v == null) {
            throw new GalilException(Tc.UNRECOGNIZED);
        }
        return v;
    }

    @Override
    public double array(String name, int index) throws GalilException {
        double[] a = arrays.get(name);
        if (a == null) {
            throw new GalilException(Tc.BAD_FUNCTION);
        }
        if (index >= a.length) {
            throw new GalilException(Tc.BAD_INDEX);
        }
        return a[index];
    }

    @Override
    public double io(String function, int n) throws GalilException {
        if (n < 1 || n > model.outputs) {
            throw new GalilException(Tc.RANGE);
        }
        long bits = function.equals("IN") ? inputs : outputs;
        return (bits >> (n - 1) & 1) != 0 ? 1 : 0;
    }

    @Override
    public double operand(String name) throws GalilException {
        return Operands.read(this, name);
    }

    // ---- reading state for a status line or a test ----

    /** The commanded position of axis {@code a} (counts, whole). */
    public synchronized long position(int a) {
        return (long) Math.rint(motion.position[a]);
    }

    public synchronized boolean moving() {
        return motion.running() || gearing.anyMoving();
    }

    public synchronized boolean output(int n) {
        return (outputs >> (n - 1) & 1) != 0;
    }

    public synchronized double offset(int axis) {
        return offsets[axis];
    }

    public synchronized String programText() {
        return program.upload();
    }

    public synchronized void close() {
        if (trace != null) {
            trace.close();
        }
    }
}
