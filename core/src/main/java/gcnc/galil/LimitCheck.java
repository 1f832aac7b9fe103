package gcnc.galil;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import gcnc.machine.ControllerLimits;
import gcnc.machine.GalilModel.Limit;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * Every number the galil dialect hands the controller, held against the profile's Galil model
 * (tables/galil_models.csv; docs/galil.md, "The controller's limits"), on its way to the output:
 * VS and the segment speeds, VA/VD, each VP segment's length, each CR's radius and radius × sweep,
 * WT, the segments and the length of each sequence, each label; and at the end of the program its
 * lines and labels against the program memory ({@link #finish}). A value beyond a limit is an error
 * at the G-code block it came from (a header's at line 1), naming the value, the limit and the model.
 */
public final class LimitCheck implements Consumer<Instruction> {
    private final ControllerLimits limits;
    private final Diagnostics diagnostics;
    private final Consumer<Instruction> next;
    private long lines;
    private int labels;
    /** The sequence being buffered: segments, length, where the last segment ended (from the sequence's start). */
    private int segments;
    private double length;
    private double u;
    private double v;
    /** VE given before BGS (the whole sequence in the buffer); BGS given before VE (a sequence fed while it runs). */
    private boolean ended;
    private boolean begun;

    public LimitCheck(ControllerLimits limits, Diagnostics diagnostics, Consumer<Instruction> next) {
        this.limits = limits;
        this.diagnostics = diagnostics;
        this.next = next;
    }

    @Override
    public void accept(Instruction i) {
        lines++;
        i.command().accept(new Limits(i));
        next.accept(i);
    }

    /**
     * The limits one command is held against, a method per command (Command.Visitor), so that a new
     * command does not compile until it is said here whether it has a limit.
     */
    private final class Limits implements Command.Visitor<Void> {
        private final Instruction i;

        Limits(Instruction i) {
            this.i = i;
        }

        private Void none() {
            return null;
        }

        /** A command whose one limit is {@code v}. */
        private Void held(Optional<ControllerLimits.Violation> v) {
            report(v, i);
            return null;
        }

        @Override public Void vectorSpeed(Command.VectorSpeed s) { return held(limits.vectorSpeed(s.countsPerSecond().unscaled())); }
        @Override public Void vectorAcceleration(Command.VectorAcceleration a) { return held(limits.acceleration(a.countsPerSecond2().unscaled())); }
        @Override public Void vectorDeceleration(Command.VectorDeceleration d) { return held(limits.acceleration(d.countsPerSecond2().unscaled())); }
        @Override public Void await(Command.Wait w) { return held(limits.dwell(w.milliseconds())); }

        @Override
        public Void vectorPosition(Command.VectorPosition p) {
            report(limits.segment(Math.round(p.first() - u), Math.round(p.second() - v)), i);
            segment(i, Math.hypot(p.first() - u, p.second() - v), p.first(), p.second(), p.speeds());
            return null;
        }

        @Override
        public Void circularArc(Command.CircularArc a) {
            long r = a.radius().unscaled();
            Optional<ControllerLimits.Violation> range = limits.arcRadius(r);
            report(range.isPresent() ? range : limits.arc(r, a.sweep().value()), i); // one finding per CR
            double from = Math.toRadians(a.start().value());
            double to = Math.toRadians(a.start().value() + a.sweep().value());
            double radius = a.radius().value();
            segment(i, Math.abs(Math.toRadians(a.sweep().value())) * radius,
                    u + radius * (Math.cos(to) - Math.cos(from)), v + radius * (Math.sin(to) - Math.sin(from)), a.speeds());
            return null;
        }

        @Override
        public Void beginSequence(Command.BeginSequence c) {
            report(limits.check(Limit.BUFFER_SEGMENTS, segments), i); // the segments given before BGS (COMALL VM)
            if (ended) {
                sequenceEnd(i);
            } else {
                begun = true; // a sequence fed while it runs: its VE comes later, its segments count from here
                segments = 0;
            }
            return null;
        }

        @Override
        public Void vectorEnd(Command.VectorEnd c) {
            if (begun) {
                sequenceEnd(i);
            } else {
                ended = true;
            }
            return null;
        }

        @Override
        public Void label(Command.Label l) {
            labels++;
            report(limits.check(Limit.LABEL_LENGTH, l.name().length()), i);
            return null;
        }

        // the commands without a limit of their own

        @Override public Void servoHere(Command.ServoHere c) { return none(); }
        @Override public Void vectorMode(Command.VectorMode c) { return none(); }
        @Override public Void stock(Command.Stock c) { return none(); }
        @Override public Void feedMark(Command.FeedMark c) { return none(); }
        @Override public Void sourceMark(Command.SourceMark c) { return none(); }
        @Override public Void remark(Command.Remark c) { return none(); }
        @Override public Void awaitSequence(Command.AwaitSequence c) { return none(); }
        @Override public Void afterVector(Command.AfterVector c) { return none(); }
        @Override public Void offset(Command.Offset c) { return none(); }
        @Override public Void toolNumber(Command.ToolNumber c) { return none(); }
        @Override public Void revolver(Command.Revolver c) { return none(); }
        @Override public Void passThroughM(Command.PassThroughM c) { return none(); }
        @Override public Void output(Command.Output c) { return none(); }
        @Override public Void gearMaster(Command.GearMaster c) { return none(); }
        @Override public Void syncPoint(Command.SyncPoint c) { return none(); }
        @Override public Void waitPast(Command.WaitPast c) { return none(); }
        @Override public Void gearRatio(Command.GearRatio c) { return none(); }
        @Override public Void phaseError(Command.PhaseError c) { return none(); }
        @Override public Void incrementPosition(Command.IncrementPosition c) { return none(); }
        @Override public Void definePosition(Command.DefinePosition c) { return none(); }
        @Override public Void positionAbsolute(Command.PositionAbsolute c) { return none(); }
        @Override public Void begin(Command.Begin c) { return none(); }
        @Override public Void afterMotion(Command.AfterMotion c) { return none(); }
        @Override public Void end(Command.End c) { return none(); }
        @Override public Void analogOut(Command.AnalogOut c) { return none(); }
        @Override public Void axisSetting(Command.AxisSetting c) { return none(); }
        @Override public Void softLimit(Command.SoftLimit c) { return none(); }
        @Override public Void jump(Command.Jump c) { return none(); }
        @Override public Void call(Command.Call c) { return none(); }
        @Override public Void message(Command.Message c) { return none(); }
        @Override public Void stop(Command.Stop c) { return none(); }
        @Override public Void abort(Command.Abort c) { return none(); }
        @Override public Void clearStack(Command.ClearStack c) { return none(); }
        @Override public Void setVariable(Command.SetVariable c) { return none(); }
        @Override public Void setDeadline(Command.SetDeadline c) { return none(); }
    }

    /** The sequence's whole length against the model's, and the next one starts from its origin. */
    private void sequenceEnd(Instruction i) {
        report(limits.check(Limit.SEQUENCE_LENGTH, length), i);
        segments = 0;
        length = 0;
        u = 0;
        v = 0;
        begun = false;
        ended = false;
    }

    private void segment(Instruction i, double len, double toU, double toV, Command.Speeds speeds) {
        segments++;
        length += len;
        u = toU;
        v = toV;
        if (speeds.speed() != 0) {
            report(limits.cornerSpeed(speeds.speed()), i);
        }
        if (speeds.end() != 0) {
            report(limits.cornerSpeed(speeds.end()), i);
        }
    }

    /**
     * The program's labels against the model's limit. Its lines are the form's to judge: a program
     * longer than the memory is written in the stream form ({@link gcnc.dmc.FormChoice}).
     */
    public void finish() {
        limits.check(Limit.LABELS, labels).ifPresent(x -> diagnostics.report(x.diagnostic(Span.of(1, 1))));
    }

    /** How many lines have passed. */
    public long lines() {
        return lines;
    }

    private void report(Optional<ControllerLimits.Violation> v, Instruction i) {
        if (v.isPresent()) {
            Diagnostic d = v.get().diagnostic(Span.of(Math.max(1, i.source().line()), 1));
            diagnostics.report(i.source().line() > 0 ? d.in(i.source().origin()) : d);
        }
    }
}
