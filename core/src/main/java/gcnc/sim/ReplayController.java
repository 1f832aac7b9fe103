package gcnc.sim;

import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import gcnc.dmc.SequencePart;
import gcnc.machine.Plane;
import java.util.ArrayList;
import java.util.List;

/**
 * The controller: what a Galil does with the commands gcnc emits (docs/dmc-format.md, both
 * dialects), one {@link Command} at a time, handed on to a {@link ReplayListener} as what the
 * machine does: vector sequences when BGS starts them, dwells, tool changes, output changes. It
 * holds the controller's state (position in whole counts and the sequence being buffered, in its
 * {@link VectorBuffer}; speed, acceleration and the program's end, in its {@link ReplayCommands};
 * the gearing of a thread pass, in its {@link ThreadGearing}) and no checks of the machine around
 * it: those are the {@link Simulator}'s. Here is when each command runs: in program order, but
 * the trip points of a sequence fed while it runs (BGS before VE) wait for its replay. A command
 * that makes no sense where it stands (another plane, a gear ratio with no master, anything after
 * EN) is reported, never skipped silently. Positions are Galil coordinates in the vector plane;
 * {@link Plane} turns them into machine counts.
 */
final class ReplayController {
    private final VectorBuffer buffer;
    private final ReplayCommands commands;
    /**
     * The trip points (AV) given while a sequence begun before its VE is fed, with the commands after
     * each (the outputs it switches): run once the sequence is replayed, in order, as those after VE.
     */
    private final List<Instruction> deferred = new ArrayList<>();
    private boolean deferring;

    /**
     * The axes start at ({@code x}, {@code z}), machine counts, at vector acceleration {@code acc},
     * deceleration {@code dec} and speed {@code speed}; {@code spindleAnalog} is the analog output
     * that drives the spindle ({@code spindle.output = AO n}), or -1 when the spindle is the OF of
     * its channel.
     */
    ReplayController(Plane plane, double x, double z, double acc, double dec, double speed, char spindleAxis,
                     int spindleAnalog, ThreadGearing gearing, ReplayListener out, SequenceLog log) {
        this.buffer = new VectorBuffer(plane, out, log);
        this.commands = new ReplayCommands(plane, buffer, gearing, acc, dec, speed, spindleAxis, spindleAnalog,
                this::startBegun, out);
        buffer.moveTo(x, z);
    }

    /** Puts the machine at a position (machine counts): the start, or a resync after a mismatch. */
    void moveTo(double x, double z) {
        buffer.moveTo(x, z);
    }

    double x() {
        return buffer.x();
    }

    double z() {
        return buffer.z();
    }

    double acceleration() {
        return commands.acceleration();
    }

    double deceleration() {
        return commands.deceleration();
    }

    /** When a G-code block is there to compare with, conformance reports zero sweeps instead. */
    void checkedByCaller(boolean checked) {
        commands.checkedByCaller(checked);
    }

    boolean hasPending() {
        return buffer.hasPending();
    }

    void dropPending() {
        buffer.dropPending();
    }

    /**
     * A {@code NO G01} comment came before this sequence: gcnc marks a feed whose speed equals the
     * rapid speed so that a bare replay does not take it for a rapid (docs/dmc-format.md).
     */
    boolean feedMarked() {
        return buffer.feedMarked();
    }

    /**
     * Replays a sequence started by BGS whose VE has not come, as it stands: where the program
     * gives no more (a hand-written BGS without VE; gcnc writes VE with a fed sequence's last segment).
     */
    void startBegun() {
        if (buffer.begun()) {
            commands.startSequence();
            runDeferred();
        }
    }

    /**
     * Runs one instruction. Comments, labels and the marks gcnc writes are
     * taken anywhere; any other command after {@code EN} is E312.
     */
    void run(Instruction i) {
        commands.at(i);
        Command cmd = i.command();
        SequencePart part = SequencePart.of(cmd);
        boolean wait = part == SequencePart.ROOM_WAIT;
        if (buffer.begun() && (part == SequencePart.TRIP || deferring && !wait && !joinsRunning(part))) {
            // a trip point of the sequence running and what it sets (GroupWriter writes them while it is
            // fed): run after the sequence, which the replay runs whole at its VE
            deferred.add(i);
            deferring = true;
            return;
        }
        deferring = false;
        if (buffer.begun() && !buffer.fed() && !wait) {
            // A BGS before VE that no wait for room followed (a hand-written program, the thesis's object
            // program: BGS after each segment and no VE) starts its sequence as it stood at the BGS, before
            // this command runs, as the replay always ran it (an AV after it measures the sequence as it stood).
            startBegun();
        }
        commands.run(i);
    }

    /** A command that goes on with the sequence begun: a segment, its VE, the end of the wait. */
    private static boolean joinsRunning(SequencePart part) {
        return switch (part) {
            case SEGMENT, VECTOR_END, AWAIT -> true;
            case SPEED, BEGIN, ROOM_WAIT, TRIP, OUTSIDE, NONE -> false;
        };
    }

    /** Runs the trip points deferred while the sequence was fed, after the replay of the sequence. */
    private void runDeferred() {
        if (deferred.isEmpty()) {
            return;
        }
        List<Instruction> now = new ArrayList<>(deferred);
        deferred.clear();
        Instruction was = commands.instruction();
        for (Instruction d : now) {
            commands.run(d);
        }
        commands.at(was);
    }
}
