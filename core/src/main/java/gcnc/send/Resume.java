package gcnc.send;

import gcnc.diag.Code;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * The program that continues an interrupted run at a {@link ResumePoint}, built from the compiled
 * program's own lines (docs/run.md, "Resume"):
 * <ol>
 * <li>the program's header ({@code #GCNC}, {@code SH}, {@code VM}, {@code VA}, {@code VD});
 * <li>the state the controller holds at that point as the program set it: the last spindle
 *     {@code OF}, the last {@code TOOL=}, and every output bit the program switched ({@code SB}/
 *     {@code CB}) at its last value; then {@code WT 2000} when the spindle turns, for it to reach
 *     speed (the profile gives no spin-up time). Offsets, units and feed mode (G94/G95, G96) need
 *     nothing: the compiler resolved them into the counts and speeds of every later line;
 * <li>when the axes stopped inside the motion to resume, the rest of that motion re-planned from
 *     where they are (the remaining part of the line or arc, then its other segments, as one
 *     sequence at the motion's own VS), else nothing;
 * <li>the program's lines from the resume point to its end, unchanged.
 * </ol>
 * The axes must be at the point's start, or on the path of the motion to resume (they stopped
 * there), or at its end; anywhere else gcnc does not invent a move through the part: E827.
 */
public final class Resume {
    private final DmcProgram program;
    private final double tolerance;

    /** @param tolerance how far (counts) the axes may be from the path and still be on it */
    public Resume(DmcProgram program, double tolerance) {
        this.program = program;
        this.tolerance = tolerance;
    }

    public Piece plan(ResumePoint at, double[] axes) throws RunFault {
        int first = program.firstLineOf(at.line());
        if (first < 0) {
            throw fault(at, "line " + at.line() + " has no block that reached the controller (a comment, an empty line"
                    + " or beyond the program): name the line of a block");
        }
        List<Sequence> motions = program.sequencesOf(at.line());
        if (at.motion() > motions.size()) {
            throw fault(at, "line " + at.line() + " makes " + motions.size() + " motion" + (motions.size() == 1 ? "" : "s"));
        }
        Sequence s = at.motion() > 0 ? motions.get(at.motion() - 1) : motions.isEmpty() ? null : motions.get(0);
        int from = at.motion() > 0 ? s.first() : first;
        double[] start = s != null ? s.start() : positionAt(first);
        if (near(axes, start)) {
            return build(from, from, null);
        }
        if (s == null) {
            throw fault(at, away(axes, start));
        }
        if (near(axes, s.end())) {
            return build(s.last() + 1, s.last() + 1, null);
        }
        if (s.isThreadPass()) {
            throw fault(at, "a thread pass cannot be entered part way (the spindle and Z are geared at its start): bring"
                    + " the axes to " + counts(start) + " and resume at " + at.line());
        }
        for (int k = 0; k < s.pieces().size(); k++) {
            if (onPiece(s.pieces().get(k), axes)) {
                return build(s.last() + 1, s.first(), replan(s, k, axes));
            }
        }
        throw fault(at, "the axes are at " + counts(axes) + ", not on the path of line " + at.line() + " (" + counts(s.start())
                + " to " + counts(s.end()) + "): jog them to " + counts(start) + " and resume again");
    }

    /** Where the axes are when program line {@code index} starts. */
    private double[] positionAt(int index) {
        double[] p = null;
        for (Sequence q : program.sequences()) {
            if (q.last() < index) {
                p = q.end();
            }
        }
        if (p == null) {
            Sequence firstMotion = program.sequences().isEmpty() ? null : program.sequences().get(0);
            return firstMotion == null ? new double[] {0, 0} : firstMotion.start();
        }
        return p;
    }

    /**
     * @param from      the first of the program's lines to run unchanged
     * @param stateEnd  the state is what the lines before this one set
     * @param replanned the rest of an interrupted motion, or null
     */
    private Piece build(int from, int stateEnd, Piece.Builder replanned) {
        Piece.Builder b = new Piece.Builder();
        List<String> lines = program.lines();
        int header = 0;
        while (header < lines.size() && program.sourceLine(header) == 0 && !lines.get(header).strip().equals("EN")) {
            // not the homing check: a resumed run starts where the axes stopped, which the sender checks itself
            if (!lines.get(header).strip().startsWith("JP #NOHOME")) {
                b.add(lines.get(header), header);
            }
            header++;
        }
        String of = null;
        int ofAt = -1;
        String tool = null;
        int toolAt = -1;
        Map<Integer, String[]> bits = new TreeMap<>();
        for (int i = header; i < stateEnd && i < lines.size(); i++) {
            String l = lines.get(i).strip();
            String op = DmcProgram.op(l);
            if (op.equals("OF")) {
                of = l;
                ofAt = i;
            } else if (l.toUpperCase(Locale.ROOT).startsWith("TOOL=")) {
                tool = l;
                toolAt = i;
            } else if ((op.equals("SB") || op.equals("CB")) && l.substring(2).strip().matches("\\d+")) {
                bits.put(Integer.parseInt(l.substring(2).strip()), new String[] {l, Integer.toString(i)});
            }
        }
        if (tool != null) {
            b.add(tool, toolAt);
        }
        for (String[] bit : bits.values()) {
            b.add(bit[0], Integer.parseInt(bit[1]));
        }
        if (of != null) {
            b.add(of, ofAt);
            if (spins(of)) {
                b.add("WT 2000", ofAt);
            }
        }
        if (replanned != null) {
            Piece r = replanned.build();
            for (int i = 0; i < r.lines().size(); i++) {
                b.add(r.lines().get(i), r.origin()[i]);
            }
        }
        for (int i = Math.max(from, header); i < lines.size(); i++) {
            b.add(lines.get(i), i);
        }
        return b.build();
    }

    private static boolean spins(String of) {
        for (String v : of.substring(2).split(",")) {
            if (!v.isBlank() && Double.parseDouble(v.strip()) != 0) {
                return true;
            }
        }
        return false;
    }

    /** The rest of sequence {@code s} from {@code axes}, on its piece {@code k}: one sequence of its own. */
    private Piece.Builder replan(Sequence s, int k, double[] axes) {
        int at = s.first();
        Piece.Builder b = new Piece.Builder();
        b.add("VS " + Math.round(s.speed()), at);
        double[] cursor = axes;
        for (int j = k; j < s.pieces().size(); j++) {
            Sequence.Piece p = s.pieces().get(j);
            if (p instanceof Sequence.Arc a) {
                double theta = j == k ? Math.toDegrees(Math.atan2(axes[1] - a.centre()[1], axes[0] - a.centre()[0])) : a.theta();
                double end = a.theta() + a.delta();
                double delta = j == k ? sweepTo(theta, end, a.delta()) : a.delta();
                b.add(String.format(Locale.ROOT, "CR %d,%.4f,%.4f", Math.round(a.radius()), theta, delta), at);
                double[] c = {cursor[0] - a.radius() * Math.cos(Math.toRadians(theta)),
                        cursor[1] - a.radius() * Math.sin(Math.toRadians(theta))};
                cursor = new double[] {c[0] + a.radius() * Math.cos(Math.toRadians(theta + delta)),
                        c[1] + a.radius() * Math.sin(Math.toRadians(theta + delta))};
                boolean last = j == s.pieces().size() - 1;
                if (last && Math.hypot(cursor[0] - a.to()[0], cursor[1] - a.to()[1]) >= 0.5) {
                    b.add(vp(a.to(), axes), at); // the arc from the stop ends a count or so off: close on the target
                }
            } else {
                b.add(vp(p.to(), axes), at);
                cursor = p.to();
            }
        }
        b.add("VE", at).add("BGS", at).add("AMS", at);
        return b;
    }

    /** The sweep from {@code theta} to {@code end} in the direction of {@code sense}, degrees. */
    private static double sweepTo(double theta, double end, double sense) {
        double d = ((end - theta) % 360 + 360) % 360; // [0, 360)
        return sense < 0 && d > 0 ? d - 360 : d;
    }

    /** {@code VP} to {@code to} from the sequence's start {@code origin}, whole counts. */
    private static String vp(double[] to, double[] origin) {
        return "VP " + Math.round(to[0] - origin[0]) + "," + Math.round(to[1] - origin[1]);
    }

    private boolean onPiece(Sequence.Piece p, double[] q) {
        if (p instanceof Sequence.Arc a) {
            double r = Math.hypot(q[0] - a.centre()[0], q[1] - a.centre()[1]);
            if (Math.abs(r - a.radius()) > tolerance) {
                return false;
            }
            double ang = Math.toDegrees(Math.atan2(q[1] - a.centre()[1], q[0] - a.centre()[0]));
            double swept = sweepTo(a.theta(), ang, a.delta());
            return Math.abs(swept) <= Math.abs(a.delta()) + 1e-9;
        }
        double[] f = p.from();
        double[] t = p.to();
        double dx = t[0] - f[0];
        double dz = t[1] - f[1];
        double len2 = dx * dx + dz * dz;
        double u = len2 == 0 ? 0 : ((q[0] - f[0]) * dx + (q[1] - f[1]) * dz) / len2;
        if (u < 0 || u > 1) {
            return false;
        }
        return Math.hypot(f[0] + u * dx - q[0], f[1] + u * dz - q[1]) <= tolerance;
    }

    private boolean near(double[] a, double[] b) {
        return Math.hypot(a[0] - b[0], a[1] - b[1]) <= tolerance;
    }

    private static String away(double[] axes, double[] start) {
        return "the axes are at " + counts(axes) + " and the block starts at " + counts(start)
                + ": jog them there and resume again";
    }

    static String counts(double[] p) {
        return Math.round(p[0]) + "," + Math.round(p[1]);
    }

    private static RunFault fault(ResumePoint at, String why) {
        return new RunFault(Code.E827_CANNOT_RESUME, at.line(), false, at, why);
    }
}
