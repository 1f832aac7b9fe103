package gcnc.galil;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.ArcGeometry;
import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import java.util.List;

/**
 * The default dialect: a standalone DMC program (docs/dmc-format.md, docs/galil.md). Each motion is
 * its own vector sequence ending in {@code VE / BGS / AMS}, so VP is simply the displacement from
 * where the controller stands, and outputs never switch while the axes move. The controller's
 * position is tracked in whole counts so rounding never accumulates.
 */
final class GalilDialect implements Dialect {
    /** The OF output range (galil-notes.md §1); a request up to 10 V is clamped with a warning. */
    private static final double MAX_VOLTS = 9.998;
    private static final double CLAMP_LIMIT = 10.0;

    private final MachineProfile profile;
    private final Diagnostics diagnostics;
    private final boolean inlineSourceMap;
    private final GalilFrame frame;
    private long posU;
    private long posV;

    GalilDialect(MachineProfile profile, Diagnostics diagnostics, boolean inlineSourceMap) {
        this.profile = profile;
        this.diagnostics = diagnostics;
        this.inlineSourceMap = inlineSourceMap;
        this.frame = new GalilFrame(profile);
        this.posU = GalilNumbers.round(frame.u(profile.home()));
        this.posV = GalilNumbers.round(frame.v(profile.home()));
    }

    @Override
    public void begin(LineSink out) {
        String plane = frame.plane();
        out.accept(new GalilLine("#GCNC", 0));
        out.accept(new GalilLine("SH " + plane, 0));
        out.accept(new GalilLine("VM " + plane, 0));
        out.accept(new GalilLine("VA " + GalilNumbers.round(profile.acceleration()), 0));
        out.accept(new GalilLine("VD " + GalilNumbers.round(profile.deceleration()), 0));
    }

    /** {@code NO STOCK D<diameter> L<length> S<stickout>}, mm, or {@code NO STOCK NONE} (docs/dmc-format.md). */
    @Override
    public void blank(java.util.Optional<gcnc.machine.MachineModel.Blank> blank, LineSink out) {
        out.accept(new GalilLine(blank.map(StockComment::write).orElse(StockComment.NONE), 0));
    }

    @Override
    public void end(LineSink out) {
        out.accept(new GalilLine("EN", 0));
    }

    @Override
    public void block(CheckedBlock b, LineSink sink) {
        BlockWriter out = new BlockWriter(sink, b.line(), inlineSourceMap);
        if (b.spindleRpm().isPresent()) {
            spindle(b, b.spindleRpm().getAsDouble(), out);
        }
        if (b.tool().isPresent()) {
            out.emit("TOOL=" + b.tool().getAsInt());
        }
        outputs(b.before(), out);
        for (Motion m : b.motions()) {
            if (m instanceof Motion.Linear) {
                linear(b, (Motion.Linear) m, out);
            } else if (m instanceof Motion.Arc) {
                arc(b, (Motion.Arc) m, out);
            } else {
                dwell(b, (Motion.Dwell) m, out);
            }
        }
        outputs(b.after(), out);
    }

    private void spindle(CheckedBlock b, double rpm, BlockWriter out) {
        double volts = rpm / profile.rpmPerVolt();
        if (volts > CLAMP_LIMIT) {
            diagnostics.error(Code.E203_SPINDLE_VOLTS, at(b), GalilNumbers.round(rpm), GalilNumbers.volts(volts));
            return;
        }
        if (volts > MAX_VOLTS) {
            diagnostics.report(Diagnostic.warning(Code.E204_SPINDLE_VOLTS_CLAMPED, at(b),
                    GalilNumbers.round(rpm), GalilNumbers.volts(volts)));
            volts = MAX_VOLTS;
        }
        out.emit(BlockWriter.offset(frame.spindleIndex(), GalilNumbers.volts(volts)));
    }

    private void outputs(List<MCall> calls, BlockWriter out) {
        for (MCall m : calls) {
            for (String directive : profile.outputsFor(m.code())) {
                out.emit(directive);
            }
        }
    }

    private void linear(CheckedBlock b, Motion.Linear m, BlockWriter out) {
        straight(b, m.to(), m.rapid() ? null : m.feed(), out);
    }

    /** One VP sequence to {@code to} (feed null = rapid); nothing when it is the same count. */
    private void straight(CheckedBlock b, Point to, gcnc.ir.Feed feed, BlockWriter out) {
        long tu = GalilNumbers.round(frame.u(to));
        long tv = GalilNumbers.round(frame.v(to));
        long du = tu - posU;
        long dv = tv - posV;
        if (!inRange(b, "VP", tu) || !inRange(b, "VP", tv) || !inRange(b, "VP", du) || !inRange(b, "VP", dv)) {
            return;
        }
        long speed = speed(b, feed);
        if (speed < 0 || (du == 0 && dv == 0)) {
            return; // no move: an empty sequence would be TC 30 "segment too short"
        }
        speedLine(speed, feed != null, out);
        out.emit("VP " + du + "," + dv);
        finishSequence(out);
        posU = tu;
        posV = tv;
    }

    private void arc(CheckedBlock b, Motion.Arc m, BlockWriter out) {
        long tu = GalilNumbers.round(frame.u(m.to()));
        long tv = GalilNumbers.round(frame.v(m.to()));
        if (!inRange(b, "CR", tu) || !inRange(b, "CR", tv) || !inRange(b, "CR", GalilNumbers.round(m.radius()))) {
            return;
        }
        Point c = m.centre();
        double sweep = frame.handedness() * ArcGeometry.sweepDegrees(m.from(), m.to(), c, m.clockwise());
        if (2 * m.radius() < 1 || tu == posU && tv == posV && Math.abs(sweep) <= 180) {
            // The arc stays within a count of where it starts: a straight move to its end count,
            // or none (a CR would sweep 0, or draw a circle of a whole count where the program
            // has a smaller one).
            straight(b, m.to(), m.feed(), out);
            return;
        }
        ArcPlanner.Cr cr = ArcPlanner.plan(posU, posV, tu, tv, new ArcPlanner.Intended(frame.u(m.from()),
                frame.v(m.from()), frame.u(c), frame.v(c), m.radius(), sweep));
        if (cr == null) {
            diagnostics.error(Code.E202_ARC_NOT_REPRESENTABLE, at(b), GalilNumbers.round(m.radius()));
            return;
        }
        long speed = speed(b, m.feed());
        if (speed < 0) {
            return;
        }
        speedLine(speed, true, out);
        out.emit("CR " + cr.radius() + "," + GalilNumbers.angle(cr.start()) + "," + GalilNumbers.angle(cr.sweep()));
        if (cr.closing()) {
            out.emit("VP " + (tu - posU) + "," + (tv - posV)); // VP is measured from the sequence start
        }
        finishSequence(out);
        posU = tu;
        posV = tv;
    }

    private void dwell(CheckedBlock b, Motion.Dwell m, BlockWriter out) {
        long ms = GalilNumbers.round(m.seconds() * 1000);
        if (inRange(b, "WT", ms)) {
            out.emit("WT " + ms);
        }
    }

    private static void finishSequence(BlockWriter out) {
        out.emit("VE");
        out.emit("BGS");
        out.emit("AMS");
    }

    /** The vector speed in counts/s, or -1 (reported) when the controller cannot take it. */
    /**
     * The sequence's VS; a feed as fast as a rapid is marked with a {@code NO G01} comment first, so
     * that a replay of the DMC by itself knows it for a feed (docs/dmc-format.md).
     */
    private void speedLine(long speed, boolean feed, BlockWriter out) {
        if (feed && speed == GalilNumbers.round(profile.rapidSpeed())) {
            out.emit("NO G01");
        }
        out.emit("VS " + speed);
    }

    private long speed(CheckedBlock b, gcnc.ir.Feed feed) {
        double cps = feed == null ? profile.rapidSpeed() : feed.countsPerSecond();
        long s = GalilNumbers.round(cps);
        if (s < 1) {
            diagnostics.error(Code.E207_FEED_TOO_SLOW, at(b), GalilNumbers.angle(cps));
            return -1;
        }
        if (!GalilNumbers.inRange(s)) {
            diagnostics.error(Code.E201_GALIL_RANGE, at(b), "VS", s);
            return -1;
        }
        return s;
    }

    private boolean inRange(CheckedBlock b, String command, long counts) {
        if (GalilNumbers.inRange(counts)) {
            return true;
        }
        diagnostics.error(Code.E201_GALIL_RANGE, at(b), command, counts);
        return false;
    }

    private static Span at(CheckedBlock b) {
        return Span.of(b.line(), 1);
    }
}
