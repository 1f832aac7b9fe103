package gcnc.galil;

import gcnc.machine.Plane;
import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.Fixed;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import java.util.List;

/**
 * One thread pass geared to the spindle encoder, as the galil dialect writes it (docs/threading.md,
 * docs/dmc-format.md): GA, the synchronisation on a whole revolution, GR per geared segment with the
 * phase correction after the engagement, and the settle on the exact end counts. The controller's
 * position is the dialect's ({@link GalilDialect#posU}, {@link GalilDialect#posV}).
 */
final class ThreadPass {
    private final GalilDialect dialect;
    private final MachineProfile profile;
    private final Plane plane;

    ThreadPass(GalilDialect dialect, MachineProfile profile) {
        this.dialect = dialect;
        this.profile = profile;
        this.plane = dialect.plane();
    }

    /** Galil's GR range: a gear ratio between -127 and 127 (COMALL GR). */
    static final double MAX_RATIO = gcnc.machine.SpindleEncoder.MAX_RATIO;

    /** The DMC variable that holds the spindle encoder count a thread pass starts at. */
    static final String SYNC_VARIABLE = "gsp";

    /**
     * One thread pass geared to the spindle encoder (docs/threading.md, docs/dmc-format.md):
     * {@code GA} makes the encoder's channel the master of both plane axes; the DMC waits with
     * {@code MF}/{@code MR} for the encoder to pass the next whole revolution (every pass starts at
     * the same spindle angle; a multi-start thread's pass its start angle further on, {@code +phase}
     * counts); {@code GR} engages both axes at the ratios that advance Z one lead
     * per revolution (X in proportion for a taper); {@code MF}/{@code MR} on Z waits for the end of
     * that segment. At each corner (a continuous G32 thread's joint, a chamfered pull-out's start
     * under Haas M23) the ratios change while geared ({@code GR} again, no new synchronisation) and
     * Z's wait moves on to the next segment's end.
     * {@code GR 0,0} disengages, and {@code PA}/{@code BG}/{@code AM} settle both axes on the exact
     * end counts (the few counts the disengagement and the 4-decimal ratios leave).
     */
    void write(CheckedBlock b, Motion.Thread t, BlockWriter out) {
        gcnc.machine.SpindleEncoder enc = profile.encoder().orElse(null);
        if (enc == null) {
            // the checker reports E190 first; a hand-built block without an encoder is the same fault here
            dialect.error(Code.E190_NO_SPINDLE_ENCODER, b, profile.name(), "a thread");
            return;
        }
        // the geared segments: from, each corner (a continuous thread's joints, a chamfer's start), to
        List<Point> points = new java.util.ArrayList<>(t.corners().size() + 2);
        points.add(t.from());
        points.addAll(t.corners());
        points.add(t.to());
        int n = points.size();
        long[] u = new long[n];
        long[] v = new long[n];
        u[0] = dialect.posU;
        v[0] = dialect.posV;
        for (int i = 1; i < n; i++) {
            u[i] = GalilNumbers.round(plane.galil1(points.get(i)));
            v[i] = GalilNumbers.round(plane.galil2(points.get(i)));
            String cmd = i == n - 1 ? "PA" : "MF";
            if (!dialect.inRange(b, cmd, u[i]) || !dialect.inRange(b, cmd, v[i])) {
                return;
            }
        }
        double[][] ratios = new double[n - 1][];
        double largest = 0;
        for (int i = 1; i < n; i++) {
            // from the geometry, not from each pass's rounded counts: every pass of a thread writes
            // the same ratio text, so the controller holds the same ratio on every pass
            ratios[i - 1] = ratios(enc, t, points.get(i - 1), points.get(i),
                    plane.galil1(points.get(i)) - plane.galil1(points.get(i - 1)), plane.galil2(points.get(i)) - plane.galil2(points.get(i - 1)));
            largest = Math.max(largest, Math.max(Math.abs(ratios[i - 1][0]), Math.abs(ratios[i - 1][1])));
        }
        if (largest > MAX_RATIO) {
            dialect.error(Code.E208_GEAR_RATIO_RANGE, b, ratio(largest));
            return;
        }
        char p1 = plane.letters().charAt(0);
        char p2 = plane.letters().charAt(1);
        char encoder = enc.channel();
        boolean zFirst = p1 == profile.z().galil();
        long[] z = zFirst ? u : v;
        out.emit(new Command.GearMaster(encoder, p1, p2));
        int cpr = enc.countsPerRev();
        // a multi-start thread's pass starts its start angle further on, in the spindle's direction
        long phase = Math.round(t.startAngle() / 360 * cpr) % cpr;
        out.emit(new Command.SyncPoint(SYNC_VARIABLE, encoder, cpr, t.reverse(), t.reverse() ? -phase : phase));
        out.emit(new Command.WaitPast(t.reverse(), encoder, new Command.Operand.Variable(SYNC_VARIABLE)));
        char zLetter = profile.z().galil();
        boolean zBack = z[n - 1] < z[0]; // a thread's Z goes one way through all its segments
        for (int i = 1; i < n; i++) {
            out.emit(new Command.GearRatio(p1, Fixed.of(ratio(ratios[i - 1][0])), p2, Fixed.of(ratio(ratios[i - 1][1]))));
            if (i == 1) {
                phaseCorrection(p1, p2, ratios[0], encoder, out);
            }
            // wait for Z to pass the segment's end: the next segment's ratios, or the pass's end
            out.emit(new Command.WaitPast(zBack, zLetter, new Command.Operand.Count(z[i])));
        }
        out.emit(new Command.GearRatio(p1, Fixed.of(0), p2, Fixed.of(0)));
        out.emit(new Command.PositionAbsolute(p1, u[n - 1], p2, v[n - 1]));
        out.emit(new Command.Begin(plane.letters()));
        out.emit(new Command.AfterMotion(plane.letters()));
        dialect.posU = u[n - 1];
        dialect.posV = v[n - 1];
    }

    /** The DMC variables of the slaves' phase errors (first and second plane axis). */
    static final String PHASE_FIRST = "gpu";

    static final String PHASE_SECOND = "gpv";

    /**
     * Right after the engagement, the phase correction (docs/threading.md, "One groove"): GR took
     * effect up to two samples after the spindle passed {@code gsp} (COMALL MF: "The accuracy of the
     * MF command is the number of counts that occur in 2*TM"), so each geared slave stands behind
     * the helix that starts at gsp by its ratio × the master's counts since gsp at engagement. Each
     * slave's lag is read in one expression (the master's counts past gsp × {@code _GR}, less its
     * commanded travel since it stood at its start, {@code _RP}) and added by {@code IP}, which on a
     * geared slave is a move "superimposed on top of the existing gearing motion" (COMALL IP). A
     * slave at ratio 0 (X of a straight thread) does not move and is not corrected.
     */
    private void phaseCorrection(char p1, char p2, double[] ratio, char encoder, BlockWriter out) {
        boolean first = !ratio(ratio[0]).equals(ratio(0));
        boolean second = !ratio(ratio[1]).equals(ratio(0));
        if (first) {
            out.emit(new Command.PhaseError(PHASE_FIRST, encoder, SYNC_VARIABLE, p1, dialect.posU));
        }
        if (second) {
            out.emit(new Command.PhaseError(PHASE_SECOND, encoder, SYNC_VARIABLE, p2, dialect.posV));
        }
        if (first && second) {
            out.emit(new Command.IncrementPosition(p1, PHASE_FIRST, p2, PHASE_SECOND));
        } else if (first || second) {
            out.emit(new Command.IncrementPosition(first ? p1 : p2, first ? PHASE_FIRST : PHASE_SECOND, (char) 0, ""));
        }
    }

    /**
     * The gear ratios of one geared segment of a pass from {@code a} to {@code b}: its displacement
     * in counts ({@code du}, {@code dv}, Galil's plane order, unrounded) over the encoder counts the
     * spindle turns while Z goes from a to b at the lead (negative under M04).
     */
    static double[] ratios(gcnc.machine.SpindleEncoder enc, Motion.Thread t, Point a, Point b, double du,
                                   double dv) {
        double master = Math.abs(b.z() - a.z()) / t.lead() * enc.countsPerRev() * (t.reverse() ? -1 : 1);
        return new double[] {du / master, dv / master};
    }

    /** A gear ratio as GR takes it: four decimals (its resolution, DMC-40x0 command reference). */
    static String ratio(double r) {
        String s = String.format(java.util.Locale.ROOT, "%.4f", r);
        return s.equals("-0.0000") ? "0.0000" : s;
    }
}
