package gcnc.send;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Messages;
import gcnc.dmc.Command;
import gcnc.dmc.DmcPrinter;
import gcnc.dmc.Fixed;
import gcnc.dmc.Instruction;
import gcnc.dmc.Source;
import gcnc.machine.MachineProfile;
import gcnc.sim.SimOptions;
import gcnc.sim.Simulator;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Supplier;

/**
 * {@code gcnc run --resume-at N --way-back FEED} (docs/run.md, "Resume"): the {@link WayBack} E827
 * advises, made on the controller before the resume, each leg a vector sequence of its own at the
 * stated feed. Before anything moves the feed is held against the machine's fastest cutting feed
 * (E837), the legs are replayed by the simulator on the stock as the compiled program cut it up to
 * the resume point's sequence (E838, E840), and the operator types the word (E839).
 */
public final class WayBackRun {
    /** The word the operator types to let the way back move the axes. */
    public static final String WORD = Operator.MOTION_WORD;

    /**
     * What the way back needs of the run.
     *
     * @param feed      program units per minute (the resume point's block's units)
     * @param confirmed asks the operator for {@link #WORD}: null when typed, else why it was not
     * @param onBlank   the machine the program was judged on (the work offsets on the blank)
     * @param sim       the simulation the compile ran (its stock)
     */
    public record Ask(double feed, Supplier<String> confirmed, MachineProfile onBlank, SimOptions sim) {
    }

    private final DmcProgram program;
    private final BlockTable blocks;
    private final MachineProfile profile;
    private final Messages messages;
    private final Ask ask;

    public WayBackRun(DmcProgram program, BlockTable blocks, MachineProfile profile, Messages messages, Ask ask) {
        this.program = program;
        this.blocks = blocks;
        this.profile = profile;
        this.messages = messages;
        this.ask = ask;
    }

    /** Each leg's vector speed, counts/s: the feed along the one axis it moves. */
    long[] speeds(WayBack way, ResumePoint at) throws RunFault {
        BlockTable.Block b = blocks.at(way.line());
        double mmPerMin = ask.feed() * (b != null && b.inch() ? 25.4 : 1);
        double perX = profile.x().countsPerMm();
        double perZ = profile.z().countsPerMm();
        long[] speeds = new long[way.legs().size()];
        for (int k = 0; k < speeds.length; k++) {
            double per = way.legs().get(k).kind() == WayBack.Leg.Kind.Z ? perZ : perX;
            speeds[k] = Math.round(mmPerMin / 60 * per);
        }
        long fastest = java.util.Arrays.stream(speeds).max().orElse(0);
        if (!(ask.feed() > 0) || fastest < 1) {
            throw fault(Code.E837_WAY_BACK_FEED, at, ResumeState.trim(ask.feed()), "give a feed above 0 (never a rapid)");
        }
        if (fastest > profile.maxFeed()) {
            double top = profile.maxFeed() * 60 / Math.max(perX, perZ) / (b != null && b.inch() ? 25.4 : 1);
            throw fault(Code.E837_WAY_BACK_FEED, at, ResumeState.trim(ask.feed()), "the machine's fastest cutting feed is F"
                    + ResumeState.trim(Math.floor(top * 1000) / 1000));
        }
        return speeds;
    }

    /**
     * The legs replayed by the simulator after the compiled program's lines before {@code cut} (the first
     * compiled line of the resume point's sequence: the stock as cut there, or with more left on it), from
     * where the axes stand, as rapids: a leg that touches the stock, the holder in it, the chuck or the
     * tailstock, or leaves the travel, is a finding, so a leg may take no material at all (E838).
     */
    void check(WayBack way, ResumePoint at, int cut) throws RunFault {
        Diagnostics found = new Diagnostics();
        Simulator sim = new Simulator(ask.onBlank(), ask.sim(), found);
        if (found.sorted().stream().anyMatch(d -> d.code() == Code.E316_SIM_NO_STOCK)) {
            throw fault(Code.E840_WAY_BACK_UNCHECKED, at, "the simulation has no stock to check the legs against"
                    + " (give the blank with --stock)");
        }
        // the compiled program's lines as the compile's simulator replayed them (DmcProgram keeps them)
        sim.replay(program.instructions().subList(0, Math.min(cut, program.size())));
        double[] m = program.plane().machine(way.from());
        sim.placeAxes(m[0], m[1]);
        double[] from = way.from();
        long rapid = Math.round(profile.rapidSpeed());
        for (int k = 0; k < way.legs().size(); k++) {
            WayBack.Leg leg = way.legs().get(k);
            if (none(from, leg.to())) {
                continue;
            }
            Set<Diagnostic> before = new HashSet<>(found.sorted());
            List<Instruction> lines = new ArrayList<>();
            for (Command c : leg(from, leg.to(), rapid)) {
                lines.add(new Instruction(c, Source.line(way.line())));
            }
            lines.add(new Instruction(new Command.AwaitSequence(gcnc.plan.Stop.EXACT_STOP), Source.line(way.line())));
            sim.replay(lines);
            for (Diagnostic d : found.sorted()) {
                if (!before.contains(d) && d.severity() == gcnc.diag.Severity.ERROR) {
                    throw fault(Code.E838_WAY_BACK_COLLIDES, at, name(leg.kind()), way.words().get(k),
                            Integer.toString(program.sourceLine(cut)), "E" + d.code().id() + " "
                                    + messages.render(d.code(), messages.arguments(d.args())));
                }
            }
            from = leg.to();
        }
    }

    /** One leg as a vector sequence from {@code from} to {@code to} (plane counts) at {@code speed} counts/s. */
    private static List<Command> leg(double[] from, double[] to, long speed) {
        return List.of(new Command.VectorSpeed(Fixed.of(speed)),
                new Command.VectorPosition(Math.round(to[0] - from[0]), Math.round(to[1] - from[1])),
                new Command.VectorEnd(), new Command.BeginSequence());
    }

    /** The checks of {@link #make} without the word or the motion, for a dry run: the feed's and the simulator's. */
    void verify(WayBack way, ResumePoint at, EventSink events, int cut) throws RunFault {
        speeds(way, at);
        check(way, at, cut);
        events.accept(new Event.Message("dry run: the way back was checked and not made: " + way.text()));
    }

    /**
     * Makes the way back after the operator typed the word: the program's header's servo on, vector mode,
     * acceleration and deceleration, then each leg, waiting for it to end (_BGS = 0) before the next; a
     * hold or a stop of the operator's stops the axes (E828).
     */
    void make(WayBack way, ResumePoint at, MachineLink c, EventSink events, Operator operator, int cut)
            throws RunFault, IOException {
        long[] speeds = speeds(way, at);
        check(way, at, cut);
        String why = ask.confirmed().get();
        if (why != null) {
            throw fault(Code.E839_WAY_BACK_NOT_CONFIRMED, at, "'" + WORD + "'", why);
        }
        for (int i = 0; i < program.size() && program.sourceLine(i) == 0; i++) {
            Command h = program.command(i);
            if (h instanceof Command.ServoHere || h instanceof Command.VectorMode || h instanceof Command.VectorAcceleration
                    || h instanceof Command.VectorDeceleration) {
                c.require(DmcPrinter.print(h));
            }
        }
        double[] from = c.position();
        for (int k = 0; k < way.legs().size(); k++) {
            WayBack.Leg leg = way.legs().get(k);
            if (none(from, leg.to())) {
                continue; // the axes are already as far away as the clear X (or at it)
            }
            events.accept(new Event.Message("way back: " + name(leg.kind()) + ", to " + way.words().get(k)));
            for (Command cmd : leg(from, leg.to(), speeds[k])) {
                c.require(DmcPrinter.print(cmd));
            }
            long until = System.currentTimeMillis() + 600_000;
            while (c.client().number("_BGS") != 0) {
                if (operator.stopped() || operator.held()) {
                    // q, Ctrl-C or the studio's Stop: the way back ends where it is, and so does the resume
                    c.stopAll();
                    throw new RunFault(Code.E828_STOPPED_BY_OPERATOR, at.line(), true, at.line());
                }
                if (System.currentTimeMillis() > until) {
                    c.stopAll();
                    throw new RunFault(Code.E827_CANNOT_RESUME, at.line(), true, at, "the way back's "
                            + name(leg.kind()) + " leg did not end in 10 minutes: it was stopped");
                }
                try {
                    Thread.sleep(20);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    c.stopAll();
                    throw new RunFault(Code.E828_STOPPED_BY_OPERATOR, at.line(), true, at.line());
                }
            }
            from = c.position();
        }
    }

    /** A leg shorter than a count: nothing to move. */
    private static boolean none(double[] from, double[] to) {
        return Math.round(to[0] - from[0]) == 0 && Math.round(to[1] - from[1]) == 0;
    }

    private static String name(WayBack.Leg.Kind kind) {
        return switch (kind) {
            case X_CLEAR -> "X away from the part";
            case Z -> "Z";
            case X_IN -> "X in to the block's start";
        };
    }

    private static RunFault fault(Code code, ResumePoint at, String... args) {
        return new RunFault(code, at.line(), false, (Object[]) args);
    }
}
