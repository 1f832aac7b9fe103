package gcnc.send;

import gcnc.dmc.Command;
import gcnc.sim.Sequence;
import java.util.ArrayList;
import java.util.List;

/**
 * The safe way from where the axes stand back to the start of a block, when they are off the path a
 * resume can take up (docs/run.md, "Resume"): never straight, as that can cut through the part, but
 * three legs, X away from the part first, then Z, then X in to the start. The same legs are E827's
 * advice ({@link #text()}) and the move {@code gcnc run --way-back} makes, so the words and the
 * motion cannot differ.
 *
 * @param line  the G-code line whose frame the positions are written in
 * @param from  where the axes stand (plane counts)
 * @param legs  the three legs in order: {@link Leg.Kind#X_CLEAR}, {@link Leg.Kind#Z}, {@link Leg.Kind#X_IN}
 * @param words each leg's end in program terms, then its counts ({@link PositionText})
 */
public record WayBack(int line, double[] from, List<Leg> legs, List<String> words) {
    /**
     * One straight leg, along one axis of the plane.
     *
     * @param kind which of the three it is
     * @param to   where it ends (plane counts)
     */
    public record Leg(Kind kind, double[] to) {
        /** The three legs, in the order they are made. */
        public enum Kind { X_CLEAR, Z, X_IN }
    }

    public WayBack {
        from = from.clone();
        legs = List.copyOf(legs);
        words = List.copyOf(words);
    }

    /** E827's advice: "move X away from the part first, to …, then Z, to …, then X, to …". */
    public String text() {
        return "move X away from the part first, to " + words.get(0) + ", then Z, to " + words.get(1)
                + ", then X, to " + words.get(2);
    }

    /**
     * The way from {@code axes} to {@code start}, the start of G-code line {@code line} whose motion is
     * compiled line {@code index}. The clear X is where the tool came in: the end of its first motion
     * after its {@code TOOL=} (the approach the simulator checked), or, for the block that makes that
     * motion, its own start (where the tool came from). The part is on the side the tool went to next
     * from there: toward the centre line for a turning tool, so away is outward; outward for a boring
     * bar, so away is toward the centre line. Axes already farther away than the clear X keep their X.
     */
    static WayBack of(DmcProgram program, PositionText where, double tolerance, int line, int index, double[] axes,
                      double[] start) {
        int tool = -1; // the TOOL= before the block, and the next one after it
        int next = program.size();
        for (int i = 0; i < program.size(); i++) {
            if (program.command(i) instanceof Command.ToolNumber) {
                if (i < index) {
                    tool = i;
                } else {
                    next = i;
                    break;
                }
            }
        }
        // where the tool went from its TOOL= to the next (the end of each motion, and its compiled line)
        List<double[]> ends = new ArrayList<>();
        List<Integer> lines = new ArrayList<>();
        for (Sequence q : program.sequences()) {
            if (q.first() <= tool) {
                continue;
            }
            if (q.first() > next) {
                break;
            }
            for (Sequence.Piece p : q.pieces()) {
                ends.add(p.to());
                lines.add(p.line());
            }
            if (q.isThreadPass()) {
                ends.add(q.end());
                lines.add(q.first());
            }
        }
        boolean approaching = ends.isEmpty() || lines.get(0) >= index; // the block makes the tool's first motion
        double[] clear = approaching ? start : ends.get(0);
        double cx = Math.abs(x(program, where, line, clear));
        boolean outward = true;
        for (int k = approaching ? 0 : 1; k < ends.size(); k++) {
            double[] e = program.plane().machine(ends.get(k));
            if (Math.abs(e[0] - program.plane().machine(clear)[0]) > tolerance) {
                // the tool went in toward the centre line: the part is inside
                outward = Math.abs(x(program, where, line, ends.get(k))) < cx;
                break;
            }
        }
        double[] a = program.plane().machine(axes);
        double ax = Math.abs(x(program, where, line, axes));
        double retract = outward == ax > cx ? a[0] : program.plane().machine(clear)[0];
        double[] out = program.plane().galil(retract, a[1]);
        double[] over = program.plane().galil(retract, program.plane().machine(start)[1]);
        List<Leg> legs = List.of(new Leg(Leg.Kind.X_CLEAR, out), new Leg(Leg.Kind.Z, over),
                new Leg(Leg.Kind.X_IN, start.clone()));
        return new WayBack(line, axes, legs, List.of(where.at(line, out), where.at(line, over), where.at(line, start)));
    }

    /** The X of {@code galil} as line {@code line} writes it, or its machine counts without a frame. */
    private static double x(DmcProgram program, PositionText where, int line, double[] galil) {
        double[] p = where.program(line, galil);
        return p == null ? program.plane().machine(galil)[0] : p[0];
    }
}
