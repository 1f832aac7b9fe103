package gcnc.galil;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import gcnc.machine.ControllerLimits;
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
        Command c = i.command();
        if (c instanceof Command.VectorSpeed s) {
            report(limits.vectorSpeed(s.countsPerSecond().unscaled()), i);
        } else if (c instanceof Command.VectorAcceleration a) {
            report(limits.acceleration(a.countsPerSecond2().unscaled()), i);
        } else if (c instanceof Command.VectorDeceleration d) {
            report(limits.acceleration(d.countsPerSecond2().unscaled()), i);
        } else if (c instanceof Command.VectorPosition p) {
            report(limits.segment(Math.round(p.first() - u), Math.round(p.second() - v)), i);
            segment(i, Math.hypot(p.first() - u, p.second() - v), p.first(), p.second(), p.speeds());
        } else if (c instanceof Command.CircularArc a) {
            long r = a.radius().unscaled();
            Optional<ControllerLimits.Violation> range = limits.arcRadius(r);
            report(range.isPresent() ? range : limits.arc(r, a.sweep().value()), i); // one finding per CR
            double from = Math.toRadians(a.start().value());
            double to = Math.toRadians(a.start().value() + a.sweep().value());
            double radius = a.radius().value();
            segment(i, Math.abs(Math.toRadians(a.sweep().value())) * radius,
                    u + radius * (Math.cos(to) - Math.cos(from)), v + radius * (Math.sin(to) - Math.sin(from)), a.speeds());
        } else if (c instanceof Command.BeginSequence) {
            report(limits.bufferSegments(segments), i); // the segments given before BGS (COMALL VM)
            if (ended) {
                sequenceEnd(i);
            } else {
                begun = true; // a sequence fed while it runs: its VE comes later, its segments count from here
                segments = 0;
            }
        } else if (c instanceof Command.VectorEnd) {
            if (begun) {
                sequenceEnd(i);
            } else {
                ended = true;
            }
        } else if (c instanceof Command.Wait w) {
            report(limits.dwell(w.milliseconds()), i);
        } else if (c instanceof Command.Label l) {
            labels++;
            report(limits.labelLength(l.name().length()), i);
        }
        next.accept(i);
    }

    /** The sequence's whole length against the model's, and the next one starts from its origin. */
    private void sequenceEnd(Instruction i) {
        report(limits.sequenceLength(length), i);
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
        limits.labels(labels).ifPresent(x -> diagnostics.report(x.diagnostic(Span.of(1, 1))));
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
