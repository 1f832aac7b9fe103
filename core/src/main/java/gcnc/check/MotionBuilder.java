package gcnc.check;

import gcnc.check.geom.Arcs;
import gcnc.check.geom.Coordinates;
import gcnc.check.geom.Feeds;
import gcnc.check.geom.NumberText;
import gcnc.check.geom.SpindleSpeed;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Feed;
import gcnc.ir.Letter;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.StopAt;
import gcnc.ir.Word;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalDouble;
import java.util.OptionalInt;

/**
 * Turns a block that passed its checks into what the machine does (reading §7): the end point of
 * each motion in machine counts, checked against the travel (E015 at the axis word), the arc
 * geometry, the spindle speed and the feed. Returns null after reporting an error.
 */
final class MotionBuilder {
    private final MachineProfile p;
    private final Coordinates coordinates;
    private final Arcs arcs;
    private final Feeds feeds;
    private final SpindleSpeed spindle;
    /**
     * The block's motions while it is built, cleared for each block: the block keeps an
     * unmodifiable copy ({@link #fixed}), and most blocks make one motion.
     */
    private final List<Motion> motions = new ArrayList<>(2);

    MotionBuilder(MachineProfile p, Coordinates coordinates) {
        this.p = p;
        this.coordinates = coordinates;
        this.arcs = new Arcs(p, coordinates);
        this.feeds = new Feeds(p);
        this.spindle = new SpindleSpeed(p, coordinates);
    }

    CheckedBlock build(BlockDraft d, Diagnostics out) {
        Point from = d.prior.position();
        motions.clear();
        Point end = from;
        boolean axis = d.has(Letter.X) || d.has(Letter.Z) || d.has(Letter.U) || d.has(Letter.W);
        switch (d.function) {
            case 0, 1, 2, 3 -> {
                if (axis || d.function >= 2) {
                    end = checked(d, coordinates.target(d, from), coordinates.origin(d.next), out);
                }
            }
            case 4 -> {
                double seconds = dwellSeconds(d);
                if (seconds < 0) {
                    Word w = d.has(Letter.P) ? d.word(Letter.P) : d.has(Letter.X) ? d.word(Letter.X) : d.word(Letter.U);
                    d.fail(out, Code.E122_NEGATIVE_DWELL, w.span(), w);
                    return null;
                }
                motions.add(new Motion.Dwell(seconds));
            }
            case 28 -> {
                if (!axis && d.functions.control().bareG28() == gcnc.machine.Control.BareG28.NOTHING) {
                    break; // E704: a Fanuc G28 naming no axis moves nothing
                }
                Point via = d.next.g28;
                Point home = p.home();
                end = new Point(!axis || has(d, Letter.X, Letter.U) ? home.x() : via.x(),
                        !axis || has(d, Letter.Z, Letter.W) ? home.z() : via.z());
                motions.add(new Motion.Linear(true, from, via, null));
                motions.add(new Motion.Linear(true, via, end, null));
            }
            case 29 -> {
                Point via = d.prior.g28();
                end = checked(d, coordinates.target(d, via), coordinates.origin(d.next), out);
                if (end != null) {
                    motions.add(new Motion.Linear(true, from, via, null));
                    motions.add(new Motion.Linear(true, via, end, null));
                }
            }
            case 53 -> {
                end = machineCoordinates(d, from, out);
                if (end != null) {
                    motions.add(new Motion.Linear(true, from, end, null));
                }
            }
            case 50, 92 -> register(d);
            default -> {
            }
        }
        if (end == null) {
            return null;
        }
        speed(d);
        double rpm = spindle.rpm(d, end);
        d.next.rpm = rpm;
        if (d.function >= 0 && d.function <= 3 && (axis || d.function >= 2)) {
            Motion m = move(d, from, end, rpm, out);
            if (m == null) {
                return null;
            }
            motions.add(m);
            Motion.Thread t = MotionKind.thread(m);
            if (t != null) {
                end = t.to(); // a chamfered pull-out (M23) ends out of the groove, not at the block's X
            }
        }
        d.next.position = end;
        boolean speedChanged = d.has(Letter.S) && d.function != 50
                || d.next.css && Double.compare(rpm, d.prior.rpm()) != 0;
        return new CheckedBlock(d.block.line(), speedChanged && !Double.isNaN(rpm) ? OptionalDouble.of(rpm)
                : OptionalDouble.empty(), d.has(Letter.T) ? OptionalInt.of(d.next.tool) : OptionalInt.empty(),
                fixed(d.before()), fixed(motions), fixed(d.after()), end, frame(d), gcnc.diag.Origin.PROGRAM,
                d.next.exactStopMode ? StopAt.EVERY_MOTION : d.exactStop ? StopAt.BLOCK_END : StopAt.BLEND);
    }

    /**
     * The list as the unmodifiable list a CheckedBlock keeps (which then takes it as it is): most
     * blocks have one motion and no M, and a copy of an empty or one-element list per block showed
     * in the checker's profile.
     */
    private static <T> List<T> fixed(List<T> list) {
        return switch (list.size()) {
            case 0 -> List.of();
            case 1 -> List.of(list.get(0));
            default -> List.copyOf(list);
        };
    }

    /**
     * The block's S outside a G50 block: the surface speed under G96, else the rpm, at most the
     * clamp and the machine's maximum (what the control would run; Eb07 has reported an S above
     * them, and a recovered block keeps the speed the control would have used).
     */
    private void speed(BlockDraft d) {
        if (!d.has(Letter.S) || d.function == 50) {
            return;
        }
        double s = d.value(Letter.S);
        if (d.next.css) {
            d.next.surfaceSpeed = s;
        } else {
            double clamp = Double.isNaN(d.next.rpmClamp) ? p.maxRpm() : Math.min(d.next.rpmClamp, p.maxRpm());
            d.next.rpm = Math.min(s, clamp);
        }
    }

    /** The block's program coordinates in the machine, for the simulator's findings. */
    private gcnc.ir.ProgramFrame frame(BlockDraft d) {
        return new gcnc.ir.ProgramFrame(coordinates.origin(d.next), coordinates.perX(d.units), coordinates.perZ(d.units),
                d.has(Letter.N) ? d.word(Letter.N).number() : null, null);
    }

    private Motion move(BlockDraft d, Point from, Point end, double rpm, Diagnostics out) {
        if (d.function == 0) {
            return new Motion.Linear(true, from, end, null);
        }
        if (d.thread != null && d.function == 1) {
            return thread(d, from, end, rpm, out);
        }
        Feed feed = feeds.feed(d, rpm, out);
        if (feed == null) {
            return null;
        }
        return d.function == 1 ? new Motion.Linear(false, from, end, feed) : arcs.arc(d, from, end, feed, out);
    }

    /**
     * A thread pass (docs/threading.md): the machine must have a spindle encoder (E190), the
     * spindle a constant speed (G97, E191) that it knows (E104), the pass must advance along Z at
     * least as much as along X (E196), and the lead at that speed must be within the Z axis's
     * maximum feed (E192). F is the lead per revolution whatever G98/G99 says.
     */
    private Motion thread(BlockDraft d, Point from, Point end, double rpm, Diagnostics out) {
        Word f = d.has(Letter.F) ? d.word(Letter.F) : null;
        gcnc.diag.Span at = f != null ? f.span() : d.blame();
        if (p.encoder().isEmpty()) {
            d.fail(out, Code.E190_NO_SPINDLE_ENCODER, d.blame(), p.name(), d.thread);
            return null;
        }
        if (d.next.css) {
            d.fail(out, Code.E191_THREAD_NEEDS_G97, d.blame(), d.thread);
            return null;
        }
        if (!(rpm > 0) || Double.isInfinite(rpm)) {
            d.fail(out, Code.E104_FEED_PER_REV_NO_SPEED, at);
            return null;
        }
        double lead = d.next.feed;
        if (!(lead > 0)) {
            d.fail(out, Code.E198_THREAD_LEAD, at, d.thread, NumberText.plain(lead));
            return null;
        }
        double dz = Math.abs(end.z() - from.z());
        double dx = Math.abs(end.x() - from.x());
        if (dz == 0 || dx > dz) {
            d.fail(out, Code.E196_THREAD_NOT_ALONG_Z, d.blame(), d.thread);
            return null;
        }
        double perZ = coordinates.perZ(d.units);
        double leadCounts = lead * perZ;
        double zSpeed = leadCounts * rpm / 60;
        if (zSpeed > p.maxFeed()) {
            double mmPerUnit = d.units == gcnc.machine.Units.INCH ? 25.4 : 1;
            double perMm = p.z().countsPerMm();
            d.fail(out, Code.E192_THREAD_TOO_FAST, at, d.thread, NumberText.plain(lead * mmPerUnit, 4),
                    NumberText.plain(rpm, 1), NumberText.plain(lead * mmPerUnit * rpm, 1),
                    NumberText.plain(p.maxFeed() * 60 / perMm, 1));
            return null;
        }
        // Galil's GR range (E208, as the backend finds it: here already, so check and compile give
        // one verdict): Z counts per encoder count; X's ratio is never larger (|dx| <= |dz|)
        double ratio = leadCounts / p.encoder().get().countsPerRev();
        if (ratio > gcnc.machine.SpindleEncoder.MAX_RATIO) {
            d.fail(out, Code.E208_GEAR_RATIO_RANGE, at, NumberText.plain(ratio, 4));
            return null;
        }
        double path = Math.hypot(dx, dz);
        int spindle = d.spindleBefore != BlockDraft.NONE ? d.spindleBefore : d.prior.spindle();
        Feed feed = new Feed(lead, zSpeed * path / dz, true); // the lead is per revolution
        if (d.pullOut == null) {
            return new Motion.Thread(from, end, leadCounts, rpm, spindle == 4, feed, null, d.startAngle);
        }
        Point[] chamfer = pullOut(d, from, end, lead, rpm, at, out);
        return chamfer == null ? null
                : new Motion.Thread(from, chamfer[1], leadCounts, rpm, spindle == 4, feed, chamfer[0], d.startAngle);
    }

    /**
     * The chamfered pull-out of a G76/G92 pass under Haas M23 (docs/threading.md): over the last
     * leads x lead of the pass's Z travel the tool leaves the pass's line and moves out in X at the
     * chamfer's angle to the Z axis, Z going on at the lead, both still geared to the spindle. Returns
     * {where the chamfer starts, where the pass ends}, or null after E240 (a chamfer as long as the
     * pass or longer), E241 (its end beyond the X travel), E242 (X faster than the machine's
     * feed.max) or E208 (X's gear ratio beyond GR's range).
     */
    private Point[] pullOut(BlockDraft d, Point from, Point end, double lead, double rpm, gcnc.diag.Span at,
                            Diagnostics out) {
        gcnc.machine.ThreadChamfer c = d.pullOut.chamfer();
        double perZ = coordinates.perZ(d.units);
        double perRadius = coordinates.perRadius(d.units);
        double length = c.leads() * lead; // program units along Z
        double dz = end.z() - from.z();
        if (length * perZ >= Math.abs(dz)) {
            d.fail(out, Code.E240_THREAD_CHAMFER_TOO_LONG, d.blame(), d.thread, NumberText.plain(length, 4),
                    NumberText.plain(c.leads()), NumberText.plain(lead), NumberText.plain(Math.abs(dz) / perZ, 4));
            return null;
        }
        double zc = end.z() - Math.signum(dz) * length * perZ;
        Point start = new Point(from.x() + (end.x() - from.x()) * (zc - from.z()) / dz, zc);
        Point to = new Point(start.x() + d.pullOut.side() * length * c.slope() * perRadius, end.z());
        if (!p.x().inTravel(to.x())) {
            Point zero = coordinates.origin(d.next);
            double[] travel = coordinates.programTravel(true, zero, d.units);
            d.fail(out, Code.E241_THREAD_CHAMFER_TRAVEL, d.blame(), d.thread,
                    NumberText.plain((to.x() - zero.x()) / coordinates.perX(d.units), 4), NumberText.plain(travel[0]),
                    NumberText.plain(travel[1]), p.name());
            return null;
        }
        // X's speed along the chamfer, counts/s, against feed.max as Z's is (E192)
        if (lead * perRadius * c.slope() * rpm / 60 > p.maxFeed()) {
            double mmPerUnit = d.units == gcnc.machine.Units.INCH ? 25.4 : 1;
            d.fail(out, Code.E242_THREAD_CHAMFER_TOO_FAST, at, d.thread, NumberText.plain(c.angle()),
                    NumberText.plain(lead * mmPerUnit * c.slope() * rpm, 1), NumberText.plain(lead * mmPerUnit, 4),
                    NumberText.plain(rpm, 1), NumberText.plain(p.maxFeed() * 60 / p.x().countsPerMm(), 1));
            return null;
        }
        double ratio = lead * perRadius * c.slope() / p.encoder().get().countsPerRev();
        if (ratio > gcnc.machine.SpindleEncoder.MAX_RATIO) {
            d.fail(out, Code.E208_GEAR_RATIO_RANGE, at, NumberText.plain(ratio, 4));
            return null;
        }
        return new Point[] {start, to};
    }

    /** The end point, or null after E015 when it is beyond the travel ({@code zero}: the block's coordinate zero). */
    private Point checked(BlockDraft d, Point end, Point zero, Diagnostics out) {
        return coordinates.beyondTravel(d, end, zero, out) ? null : end;
    }

    /**
     * G53: X and Z in the control's machine coordinates, whose zero is the profile's
     * {@code machine_zero} (the reference point on a Fanuc or Haas), X as a diameter where X is;
     * always absolute (E117 for U/W or under G91), the travel checked (E015).
     */
    private Point machineCoordinates(BlockDraft d, Point from, Diagnostics out) {
        for (Letter l : new Letter[] {Letter.U, Letter.W, Letter.X, Letter.Z}) {
            if (d.has(l) && (l == Letter.U || l == Letter.W || d.next.incremental)) {
                d.fail(out, Code.E117_G53_ABSOLUTE_ONLY, d.word(l).span(), d.word(l));
                return null;
            }
        }
        Point zero = p.machineZero();
        double x = d.has(Letter.X) ? zero.x() + d.value(Letter.X) * coordinates.perX(d.units) : from.x();
        double z = d.has(Letter.Z) ? zero.z() + d.value(Letter.Z) * coordinates.perZ(d.units) : from.z();
        return checked(d, new Point(x, z), zero, out);
    }

    private static boolean has(BlockDraft d, Letter a, Letter b) {
        return d.has(a) || d.has(b);
    }

    /**
     * G04: P milliseconds (where the control reads P in seconds, Haas, a P with a point is
     * seconds: P3. = 3 s, P3 = 3 ms), else X or U seconds (no-point rule of mm: X1 = 1 ms on a Fanuc).
     */
    private double dwellSeconds(BlockDraft d) {
        if (d.has(Letter.P)) {
            boolean seconds = p.control().dwellPSeconds() && NumberText.hasPoint(d.word(Letter.P).number());
            return seconds ? d.value(Letter.P) : d.value(Letter.P) / 1000;
        }
        Word w = d.has(Letter.X) ? d.word(Letter.X) : d.word(Letter.U);
        double v = NumberText.decimal(w.number());
        return NumberText.hasPoint(w.number()) ? v : v * p.noPointMm();
    }

    /** G50/G92 X Z: shift the work coordinates so the current position reads X Z. */
    private void register(BlockDraft d) {
        Point pos = d.prior.position();
        Point o = coordinates.offsets(d.next);
        double sx = d.next.shift.x();
        double sz = d.next.shift.z();
        if (d.has(Letter.X)) {
            sx = pos.x() - o.x() - d.value(Letter.X) * coordinates.perX(d.units);
        }
        if (d.has(Letter.Z)) {
            sz = pos.z() - o.z() - d.value(Letter.Z) * coordinates.perZ(d.units);
        }
        d.next.shift = new Point(sx, sz);
    }
}
