package gcnc.galil;

import gcnc.machine.Plane;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.dmc.Command;
import gcnc.dmc.Fixed;
import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import java.util.List;

/**
 * The thesis's own output (thesis-reading §7; Table 5.2): {@code VS / VP|CR / BGS} per motion,
 * {@code OF ,,<S div 300>}, {@code Revolver n}, M outputs or {@code M<n>}, {@code WT}; no header,
 * no VM/VE/AMS/EN. Numbers go through {@link DelphiFormat}. VP is the increment in Galil
 * coordinates (for thesis-2004, whose signs are -1, exactly the thesis's {@code -(new-old)}).
 * It is kept for the record and for the simulator to show what goes wrong (docs/galil.md).
 */
final class ThesisDialect implements Dialect {
    private final MachineProfile profile;
    private final Diagnostics diagnostics;
    /** One writer a block, and the blocks of the run counted. */
    private final BlockWriters writers;
    private final Plane plane;

    ThesisDialect(MachineProfile profile, Diagnostics diagnostics, boolean inlineSourceMap) {
        this.profile = profile;
        this.diagnostics = diagnostics;
        this.writers = new BlockWriters(inlineSourceMap);
        this.plane = Plane.of(profile);
    }

    @Override
    public void begin(java.util.function.Consumer<gcnc.dmc.Instruction> out) {
    }

    /** The thesis's format has no place for it: nothing. */
    @Override
    public void blank(java.util.Optional<gcnc.machine.MachineModel.Blank> blank, java.util.function.Consumer<gcnc.dmc.Instruction> out) {
    }

    @Override
    public void end(java.util.function.Consumer<gcnc.dmc.Instruction> out) {
    }

    /** The thesis's format stops at every motion: a group is written motion by motion. */
    @Override
    public void lower(gcnc.plan.Step step, java.util.function.Consumer<gcnc.dmc.Instruction> sink) {
        step.accept(new gcnc.plan.Step.Visitor() {
            @Override
            public void before(gcnc.plan.Step.Before s) {
                CheckedBlock b = s.block();
                BlockWriter out = writer(b, sink);
                if (b.spindleRpm().isPresent()) {
                    // The thesis divides the integer S by 300 as integers (L4236).
                    long volts = (long) (b.spindleRpm().getAsDouble() / profile.rpmPerVolt());
                    out.emit(new Command.Offset(profile.spindleChannel(), Fixed.of(volts)));
                }
                if (b.tool().isPresent()) {
                    out.emit(new Command.Revolver(b.tool().getAsInt()));
                }
                outputs(b.before(), out);
            }

            @Override
            public void alone(gcnc.plan.Step.Alone s) {
                BlockWriter out = writer(s.block(), sink);
                out.motion(s.motion());
                motion(s.block(), s.block().motions().get(s.motion()), out);
                out.motion(-1);
            }

            @Override
            public void group(gcnc.plan.Step.Group g) {
                for (gcnc.plan.Piece p : g.pieces()) {
                    if (p.part() == 0) { // the thesis writes a motion once, however the planner split it
                        lower(new gcnc.plan.Step.Alone(p.block(), p.motion()), sink);
                    }
                }
            }

            @Override
            public void after(gcnc.plan.Step.After s) {
                BlockWriter out = writer(s.block(), sink);
                out.motion(-1);
                outputs(s.block().after(), out);
            }
        });
    }

    private BlockWriter writer(CheckedBlock b, java.util.function.Consumer<gcnc.dmc.Instruction> sink) {
        BlockWriter w = writers.current(b);
        return w != null ? w : writers.start(b, sink);
    }

    private void motion(CheckedBlock b, Motion m, BlockWriter out) {
            m.accept(new Motion.Visitor<Void>() {
                @Override
                public Void linear(Motion.Linear l) {
                    double dx = l.to().x() - l.from().x();
                    double dz = l.to().z() - l.from().z();
                    group(b, speed(l.rapid() ? null : l.feed()), vp(b, dx, dz), out);
                    return null;
                }

                @Override
                public Void arc(Motion.Arc a) {
                    ThesisDialect.this.arc(b, a, out);
                    return null;
                }

                @Override
                public Void dwell(Motion.Dwell d) {
                    String ms = number(b, "WT", d.seconds() * 1000);
                    if (ms != null) {
                        out.emit(new Command.Wait(Long.parseLong(ms)));
                    }
                    return null;
                }

                @Override
                public Void thread(Motion.Thread t) {
                    // the thesis's directives have no gearing: a thread written as a plain feed would
                    // cut a helix of the wrong lead, at a different angle on every pass
                    diagnostics.error(Code.E209_THESIS_NO_GEARING, Span.of(b.line(), 1));
                    return null;
                }
            });
    }

    private void outputs(List<MCall> calls, BlockWriter out) {
        for (MCall m : calls) {
            List<Command> directives = MFunctions.directives(profile, m.code());
            if (directives.isEmpty()) {
                out.emit(new Command.PassThroughM(m.code())); // §7.2: any other M passes through unpadded
            }
            for (Command d : directives) {
                out.emit(d);
            }
        }
    }

    private void arc(CheckedBlock b, Motion.Arc a, BlockWriter out) {
        double dx = a.to().x() - a.from().x();
        double dz = a.to().z() - a.from().z();
        if (dx == 0 && dz == 0) {
            return; // §7.2: full circles give no output and no error
        }
        ThesisArc.Result r = ThesisArc.of(a);
        if (r == null) {
            diagnostics.error(Code.E206_THESIS_ARC, Span.of(b.line(), 1));
            return;
        }
        String radius = number(b, "CR", r.radius());
        Command cr = radius == null ? null : new Command.CircularArc(Fixed.of(radius),
                Fixed.of(DelphiFormat.fmt3x4(r.theta())), Fixed.of(DelphiFormat.fmt3x4(r.delta())));
        double speed = speed(a.feed());
        group(b, speed, cr, out);
        if (r.twoPiece()) {
            group(b, speed, vp(b, a.to().x() - r.xm(), a.to().z() - r.zm()), out);
        }
    }

    private double speed(gcnc.ir.Feed feed) {
        return feed == null ? profile.rapidSpeed() : feed.countsPerSecond();
    }

    /** {@code VS / <move> / BGS}, or nothing when a number did not fit (already reported). */
    private void group(CheckedBlock b, double speed, Command move, BlockWriter out) {
        String vs = number(b, "VS", speed);
        if (vs == null || move == null) {
            return;
        }
        out.emit(new Command.VectorSpeed(Fixed.of(vs)));
        out.emit(move);
        out.emit(new Command.BeginSequence());
    }

    private Command vp(CheckedBlock b, double dx, double dz) {
        String u = number(b, "VP", plane.galil1(dx, dz));
        String v = number(b, "VP", plane.galil2(dx, dz));
        return u == null || v == null ? null : new Command.VectorPosition(Long.parseLong(u), Long.parseLong(v));
    }

    /** fmt8, or null (reported) when Delphi would have switched to scientific notation. */
    private String number(CheckedBlock b, String command, double v) {
        if (!DelphiFormat.fits(v, 8)) {
            diagnostics.error(Code.E205_THESIS_NUMBER, Span.of(b.line(), 1), command, v);
            return null;
        }
        return DelphiFormat.fmt8(v);
    }
}
