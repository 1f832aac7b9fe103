package gcnc.sim;

import gcnc.diag.Diagnostics;
import gcnc.dmc.Instruction;
import gcnc.ir.CheckedBlock;
import gcnc.machine.MachineProfile;
import java.io.InterruptedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;

/**
 * A {@link Simulator} on a thread of its own, so that replaying block n overlaps with checking and
 * translating the blocks after it. Blocks reach it in order through a small bounded queue (memory
 * stays flat); it reports into a {@link Diagnostics} of its own, which the caller reads after
 * {@link #finish()}. A bug that throws in the simulator is rethrown by {@link #finish()} on the
 * caller's thread.
 *
 * <p>It also hands the lines it replayed on to the output, in order, so that writing them (text
 * to bytes, the source map) is done on this thread too: the checker's thread does more work
 * than the simulator's, and on two cores a compile takes as long as its busier thread. The output
 * is called only from this thread, and all of it has been called when {@link #finish()} returns.
 */
public final class SimulatorThread implements AutoCloseable {
    private static final int BATCH = 256;
    private static final int QUEUED_BATCHES = 8;
    /** Ends the queue (compared by identity). */
    private static final List<Step> DONE = new ArrayList<>();

    private enum Kind { BEGIN, BLOCK, HELD, END, OUTPUT_ONLY }

    /** One call to make on the simulator: the program's header, a block, or the footer; or lines only to hand on. */
    private record Step(Kind kind, CheckedBlock block, List<Instruction> lines, boolean settled) {
        Step(Kind kind, CheckedBlock block, List<Instruction> lines) {
            this(kind, block, lines, true);
        }
    }

    private final Diagnostics diagnostics = new Diagnostics();
    private final Simulator simulator;
    private final java.util.function.Consumer<Instruction> output;
    private final BlockingQueue<List<Step>> queue = new ArrayBlockingQueue<>(QUEUED_BATCHES);
    private final Thread thread;
    private List<Step> batch = new ArrayList<>(BATCH);
    private Throwable failure; // written by the worker, read after join()
    private boolean finished;

    /** A simulator whose lines go nowhere else. */
    public SimulatorThread(MachineProfile profile, SimOptions options) {
        this(profile, options, line -> { });
    }

    /** A simulator that hands every line it replayed on to {@code output}, in order. */
    public SimulatorThread(MachineProfile profile, SimOptions options, java.util.function.Consumer<Instruction> output) {
        this(profile, options, output, null);
    }

    /**
     * A simulator that hands every line it replayed on to {@code output}, in order, and tells
     * {@code replayed} (null: nobody) of each line with the cycle clock around it, on this thread, just
     * before the line goes to the output.
     */
    public SimulatorThread(MachineProfile profile, SimOptions options, java.util.function.Consumer<Instruction> output,
                           Simulator.Replayed replayed) {
        this.simulator = new Simulator(profile, options, diagnostics);
        simulator.onReplayed(replayed);
        this.output = output;
        this.thread = new Thread(this::work, "gcnc-simulator");
        thread.setDaemon(true);
        thread.start();
    }

    /** The program's header lines. The lists passed in must not change afterwards. */
    public void begin(List<Instruction> header) throws InterruptedIOException {
        add(new Step(Kind.BEGIN, null, header));
    }

    public void block(CheckedBlock intended, List<Instruction> emitted) throws InterruptedIOException {
        block(intended, emitted, true);
    }

    /** @param settled whether every motion meant so far has been emitted (the planner holds none back) */
    public void block(CheckedBlock intended, List<Instruction> emitted, boolean settled) throws InterruptedIOException {
        add(new Step(Kind.BLOCK, intended, emitted, settled));
    }

    /** The sequences the planner held back to the end of the program's blocks. */
    public void held(List<Instruction> lines) throws InterruptedIOException {
        add(new Step(Kind.HELD, null, lines));
    }

    public void end(List<Instruction> footer) throws InterruptedIOException {
        add(new Step(Kind.END, null, footer));
    }

    /** Lines that are not replayed (written after an error) but go to the output in their turn. */
    public void outputOnly(List<Instruction> lines) throws InterruptedIOException {
        add(new Step(Kind.OUTPUT_ONLY, null, lines));
    }

    /** Waits until the simulator has replayed all it was given; its findings, in reporting order. */
    public Diagnostics finish() throws InterruptedIOException {
        if (!finished) {
            finished = true;
            send(batch);
            send(DONE);
            try {
                thread.join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new InterruptedIOException("interrupted while waiting for the simulator");
            }
            if (failure instanceof RuntimeException r) {
                throw r;
            }
            if (failure instanceof Error e) {
                throw e;
            }
        }
        return diagnostics;
    }

    /** The summary; call after {@link #finish()}. */
    public SimReport report() {
        return simulator.report();
    }

    /** Ends the worker also when the caller gave up early (an I/O error): it drains the queue and stops. */
    @Override
    public void close() throws InterruptedIOException {
        finish();
    }

    private void add(Step step) throws InterruptedIOException {
        batch.add(step);
        if (batch.size() == BATCH) {
            send(batch);
            batch = new ArrayList<>(BATCH);
        }
    }

    private void send(List<Step> steps) throws InterruptedIOException {
        try {
            queue.put(steps);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted while feeding the simulator");
        }
    }

    private void work() {
        try {
            for (List<Step> steps = queue.take(); steps != DONE; steps = queue.take()) {
                if (failure == null) {
                    try {
                        steps.forEach(this::run);
                    } catch (RuntimeException | Error e) {
                        failure = e; // keep draining, so that the feeding thread never blocks for ever
                    }
                }
            }
        } catch (InterruptedException e) {
            failure = new IllegalStateException("simulator thread interrupted", e);
        }
    }

    private void run(Step s) {
        switch (s.kind()) {
            case BEGIN -> simulator.begin(s.lines());
            case BLOCK -> simulator.block(s.block(), s.lines(), s.settled());
            case HELD -> simulator.held(s.lines());
            case END -> simulator.end(s.lines());
            case OUTPUT_ONLY -> {
            }
        }
        for (Instruction l : s.lines()) {
            output.accept(l);
        }
    }
}
