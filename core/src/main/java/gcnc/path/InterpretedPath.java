package gcnc.path;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Feed;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.ProgramFrame;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;
import gcnc.machine.MachineProfile;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;

/**
 * The checked blocks, as the checker hands them on (cycles expanded, corners inserted, the nose
 * compensation applied, calls and macros followed: gcnc.Session#path), turned into the moves of
 * the interpreted path: one {@link PathMove} per motion. Nothing is interpreted again here: the
 * end points, centres and feeds are the checker's own {@code Motion} records, put in the program's
 * terms through each block's {@link ProgramFrame} and in millimetres through the profile's scale.
 * What it keeps between blocks is what a block does not repeat: the spindle speed and direction,
 * the tool, and where the tool is (for a dwell).
 */
public final class InterpretedPath implements Consumer<CheckedBlock> {
    private final MachineProfile profile;
    private final String programFile;
    private final Consumer<PathMove> out;
    private final Map<Integer, MRole> roles = new HashMap<>();
    private double rpm = Double.NaN;
    private String direction = "stop";
    private String tool = "";
    private Point at;

    /**
     * @param programFile the program's file as the user named it (the {@code file} of its own blocks)
     */
    public InterpretedPath(MachineProfile profile, String programFile, Consumer<PathMove> out) {
        this.profile = profile;
        this.programFile = programFile;
        this.out = out;
        this.at = profile.home();
        for (MFunction m : profile.control().allM()) {
            roles.put(m.code(), m.role());
        }
    }

    @Override
    public void accept(CheckedBlock b) {
        b.spindleRpm().ifPresent(s -> rpm = s);
        b.tool().ifPresent(t -> tool = Integer.toString(t));
        spindle(b.before());
        for (Motion m : b.motions()) {
            out.accept(m.accept(new Row(b)));
        }
        spindle(b.after());
        at = b.end();
    }

    private void spindle(List<MCall> calls) {
        for (MCall c : calls) {
            MRole r = roles.get(c.code());
            if (r == MRole.SPINDLE_CW) {
                direction = "cw";
            } else if (r == MRole.SPINDLE_CCW) {
                direction = "ccw";
            } else if (r == MRole.SPINDLE_STOP) {
                direction = "stop";
            }
        }
    }

    /** One motion of block {@code b} as a row. */
    private final class Row implements Motion.Visitor<PathMove> {
        private final CheckedBlock b;

        Row(CheckedBlock b) {
            this.b = b;
        }

        @Override
        public PathMove linear(Motion.Linear l) {
            return move(l.rapid() ? PathMove.Kind.RAPID : PathMove.Kind.FEED, l.to(), null, Double.NaN, l.feed(), "");
        }

        @Override
        public PathMove arc(Motion.Arc a) {
            return move(a.clockwise() ? PathMove.Kind.ARC_CW : PathMove.Kind.ARC_CCW, a.to(), a.centre(), a.radius(),
                    a.feed(), "");
        }

        @Override
        public PathMove dwell(Motion.Dwell d) {
            return move(PathMove.Kind.DWELL, at, null, Double.NaN, null, number(d.seconds()));
        }

        @Override
        public PathMove thread(Motion.Thread t) {
            return move(PathMove.Kind.THREAD, t.to(), null, Double.NaN, t.feed(), "");
        }

        private PathMove move(PathMove.Kind kind, Point end, Point centre, double radius, Feed feed, String seconds) {
            at = end;
            ProgramFrame f = b.frame();
            String file = b.origin().file() != null ? b.origin().file() : programFile;
            String block = f == null ? "" : f.sequence();
            String x = f == null ? "" : number((end.x() - f.origin().x()) / f.perX());
            String z = f == null ? "" : number((end.z() - f.origin().z()) / f.perZ());
            String cx = centre == null || f == null ? "" : number((centre.x() - f.origin().x()) / f.perX());
            String cz = centre == null || f == null ? "" : number((centre.z() - f.origin().z()) / f.perZ());
            String r = Double.isNaN(radius) || f == null ? "" : number(radius / f.perZ());
            String unit = f == null ? "mm" : inch(f) ? "in" : "mm";
            String fed = feed == null ? "" : number(feed.programmed());
            String feedUnit = feed == null ? "" : unit + (feed.perRevolution() ? "/rev" : "/min");
            return new PathMove(kind, file, b.line(), block, x, z, number(end.x() / profile.x().countsPerMm()),
                    number(end.z() / profile.z().countsPerMm()), cx, cz, r, fed, feedUnit,
                    Double.isNaN(rpm) ? "" : number(rpm), direction, tool, seconds);
        }
    }

    /** Whether the block's Z is programmed in inches: its counts per unit are the profile's per inch. */
    private boolean inch(ProgramFrame f) {
        double perInch = profile.z().countsPerInch();
        return Math.abs(f.perZ() - perInch) < 1e-9 * perInch;
    }

    /** A number as the formats write it: 4 decimals, never "-0.0000". */
    static String number(double v) {
        String s = String.format(Locale.ROOT, "%.4f", v);
        return s.equals("-0.0000") ? "0.0000" : s;
    }
}
