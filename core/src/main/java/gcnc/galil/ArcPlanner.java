package gcnc.galil;

import gcnc.machine.Plane;

/**
 * Turns an arc into Galil's {@code CR r,theta,delta} so that the arc the controller runs, with the
 * radius rounded to whole counts and the angles to the 4 decimals printed, ends within one count
 * of the intended end and stays within a count of the intended arc all along. All inputs are in
 * the Galil plane (first, second channel), counts.
 *
 * <p>The controller starts the arc where it is (the integer start S) and ends wherever radius and
 * angles say. With the radius rounded, the true centre in general no longer lies at that radius
 * from both rounded ends, so we use the centre C' on the same side of the chord SE that lies at the
 * rounded radius from both. Rounding the printed start angle moves the centre slightly again, so the
 * sweep is measured about the centre that the printed start angle implies. The result is checked:
 * on each axis the arc must end less than half a count from the target count, so the controller's
 * whole-count position is exactly the target and the next sequence starts where gcnc thinks.
 *
 * <p>Near a half circle that moved centre can lie many counts from the true one (the centre slides
 * along the chord's bisector by about r/h per count of radius), and the middle of the arc with
 * it. Then the true centre is kept instead: the arc stays within a count of the programmed one and
 * ends a count or two short, and the same sequence closes the gap with a VP to the target
 * ({@link Cr#closing()}), so the sequence still ends exactly where the block ends. The same holds
 * for an I/K arc whose end point is off its circle by less than the checker's tolerance (a Fanuc
 * control would run a spiral): the arc keeps the centre and the start radius, and the closing VP
 * covers the miss.
 */
public final class ArcPlanner {
    /**
     * An arc as CR prints it: radius in counts, start angle and signed sweep in degrees (as printed);
     * {@code closing}: a short VP to the target must follow in the same sequence.
     */
    public record Cr(long radius, double start, double sweep, boolean closing) {
    }

    /**
     * The arc the program means, in the Galil plane: exact start, centre and radius in counts
     * (unrounded), signed sweep in degrees (counter-clockwise positive).
     */
    public record Intended(double fromU, double fromV, double centreU, double centreV, double radius, double sweep) {
    }

    /**
     * The longest closing VP due to rounding, counts per axis; an I/K end point off its circle (by
     * less than the checker's E102 tolerance) may add its own miss. Beyond that the arc itself is
     * off, not its rounding.
     */
    private static final long MAX_CLOSING = 2;

    /** How far, in counts, an arc that lands exactly on its target may stray from the programmed arc. */
    private static final double MAX_STRAY = 1.0;

    /** The smallest printed angle step, degrees. */
    private static final double STEP = 0.0001;

    private ArcPlanner() {
    }

    /** An arc the galil dialect writes toward the whole-count target (tu, tv): its CR, or null when no printable arc ends there (E202). */
    public record Written(long tu, long tv, Cr cr) {
    }

    /**
     * What the galil dialect writes for an arc from the controller's whole-count position
     * (posU, posV): null when it writes a straight move to the end count instead (the arc stays
     * within a count of where it starts: a CR would sweep 0, or draw a circle of a whole count
     * where the program has a smaller one); else the planned CR. The backend and check's
     * prediction of the replay ({@code gcnc.sim.ArcVerdict}) both decide here, so they cannot differ.
     */
    public static Written forMotion(Plane plane, long posU, long posV, gcnc.ir.Motion.Arc m) {
        long tu = GalilNumbers.round(plane.galil1(m.to()));
        long tv = GalilNumbers.round(plane.galil2(m.to()));
        gcnc.ir.Point c = m.centre();
        double sweep = plane.handedness() * gcnc.ir.ArcGeometry.sweepDegrees(m.from(), m.to(), c, m.clockwise());
        if (2 * m.radius() < 1 || tu == posU && tv == posV && Math.abs(sweep) <= 180) {
            return null;
        }
        return new Written(tu, tv, plan(posU, posV, tu, tv, new Intended(plane.galil1(m.from()), plane.galil2(m.from()),
                plane.galil1(c), plane.galil2(c), m.radius(), sweep)));
    }

    /**
     * @param su,sv  where the sequence starts (the controller's whole-count position)
     * @param eu,ev  where the arc must end
     * @param arc    the arc the program means
     * @return the CR arguments, or null when no printable arc ends on (eu, ev)
     */
    public static Cr plan(long su, long sv, long eu, long ev, Intended arc) {
        double cu = arc.centreU();
        double cv = arc.centreV();
        double sweep = arc.sweep();
        // The nearest whole radius first; when the rounded ends are farther apart than its diameter
        // (small half circles), the next whole radius up or down may still fit.
        long r0 = GalilNumbers.round(arc.radius());
        long[] candidates = arc.radius() >= r0 ? new long[] {r0, r0 + 1, r0 - 1} : new long[] {r0, r0 - 1, r0 + 1};
        Cr best = null;
        double bestStray = Double.MAX_VALUE;
        for (long r : candidates) {
            if (Math.abs(r - arc.radius()) <= 1.5) { // rounded ends move the half chord up to 0.71
                Cr cr = withRadius(su, sv, eu, ev, cu, cv, r, sweep);
                double stray = cr == null ? Double.MAX_VALUE : stray(cr, su, sv, arc);
                if (stray <= MAX_STRAY) {
                    return cr;
                }
                if (stray < bestStray) {
                    best = cr;
                    bestStray = stray;
                }
            }
        }
        // About the true centre, with the programmed radius or the one from the controller's
        // whole-count start, whichever strays less; the closing VP may also cover how far the
        // target lies off that circle.
        double fromStart = Math.hypot(su - cu, sv - cv);
        long offCircle = (long) Math.ceil(Math.abs(Math.hypot(eu - cu, ev - cv) - fromStart));
        for (long r : new long[] {r0, GalilNumbers.round(fromStart)}) {
            Cr kept = aboutTrueCentre(su, sv, eu, ev, cu, cv, r, sweep, MAX_CLOSING + offCircle);
            double stray = kept == null ? Double.MAX_VALUE : stray(kept, su, sv, arc);
            if (stray < bestStray) {
                best = kept;
                bestStray = stray;
            }
        }
        return best; // may bow: the simulator's conformance check says so
    }

    /**
     * How far the planned arc strays from the programmed one: its centre and radius, and its
     * quarter points against the programmed arc's (both circles pass near S and E, so on a long
     * arc the far side moves by up to twice the centre's shift). The simulator's conformance
     * check compares the centre and the midpoint.
     */
    private static double stray(Cr cr, long su, long sv, Intended arc) {
        double sr = Math.toRadians(cr.start());
        double ou = su - cr.radius() * Math.cos(sr);   // the centre the controller derives
        double ov = sv - cr.radius() * Math.sin(sr);
        double programmedStart = Math.atan2(arc.fromV() - arc.centreV(), arc.fromU() - arc.centreU());
        double worst = Math.hypot(ou - arc.centreU(), ov - arc.centreV()) + Math.abs(cr.radius() - arc.radius());
        for (double t = 0.25; t < 1; t += 0.25) {
            double a = sr + Math.toRadians(t * cr.sweep());
            double b = programmedStart + Math.toRadians(t * arc.sweep());
            worst = Math.max(worst, Math.hypot(ou + cr.radius() * Math.cos(a) - arc.centreU() - arc.radius() * Math.cos(b),
                    ov + cr.radius() * Math.sin(a) - arc.centreV() - arc.radius() * Math.sin(b)));
        }
        return worst;
    }

    /** The arc of whole radius r about the true centre, ending near E (a closing VP follows), or null. */
    private static Cr aboutTrueCentre(long su, long sv, long eu, long ev, double cu, double cv, long r, double sweep,
                                      long maxClosing) {
        if (r < 1 || (su == cu && sv == cv)) {
            return null;
        }
        double start = GalilNumbers.printedAngle(Math.toDegrees(Math.atan2(sv - cv, su - cu)));
        if (start <= -180) {
            start += 360;
        }
        double sr = Math.toRadians(start);
        double ou = su - r * Math.cos(sr);
        double ov = sv - r * Math.sin(sr);
        double delta = Math.toDegrees(Math.atan2(ev - ov, eu - ou)) - start;
        delta = GalilNumbers.printedAngle(delta - 360 * Math.rint((delta - sweep) / 360));
        double er = Math.toRadians(start + delta);
        long endU = GalilNumbers.round(ou + r * Math.cos(er));
        long endV = GalilNumbers.round(ov + r * Math.sin(er));
        if (Math.abs(endU - eu) > maxClosing || Math.abs(endV - ev) > maxClosing) {
            return null;
        }
        return new Cr(r, start, delta, endU != eu || endV != ev);
    }

    private static Cr withRadius(long su, long sv, long eu, long ev, double cu, double cv, long r, double sweep) {
        if (r < 1) {
            return null;
        }
        double du = eu - su;
        double dv = ev - sv;
        double d = Math.hypot(du, dv);
        double ccu;
        double ccv;
        if (d == 0) {
            // Full circle (or an arc shorter than a count): keep the true centre's direction.
            double tu = cu - su;
            double tv = cv - sv;
            double t = Math.hypot(tu, tv);
            if (t == 0) {
                return null;
            }
            ccu = su + r * tu / t;
            ccv = sv + r * tv / t;
        } else {
            double half = d / 2;
            double h = half >= r ? 0 : Math.sqrt((double) r * r - half * half);
            double cross = du * (cv - sv) - dv * (cu - su);
            double side = cross >= 0 ? 1 : -1;     // the true centre's side of the chord
            ccu = su + du / 2 - side * h * dv / d;
            ccv = sv + dv / 2 + side * h * du / d;
        }
        double start = GalilNumbers.printedAngle(Math.toDegrees(Math.atan2(sv - ccv, su - ccu)));
        if (start <= -180) {
            start += 360;                            // keep the start angle in (-180, 180]
        }
        double sr = Math.toRadians(start);
        double ou = su - r * Math.cos(sr);          // centre implied by the printed start angle
        double ov = sv - r * Math.sin(sr);
        double end = Math.toDegrees(Math.atan2(ev - ov, eu - ou));
        double delta = end - start;
        delta -= 360 * Math.rint((delta - sweep) / 360); // the turn nearest the intended sweep
        delta = GalilNumbers.printedAngle(delta);
        // The printed sweep may land a fraction of a count off; its neighbours may land closer.
        double best = Double.NaN;
        double bestMiss = Double.MAX_VALUE;
        for (int step = -1; step <= 1; step++) {
            double candidate = delta + step * STEP;
            double er = Math.toRadians(start + candidate);
            double miss = Math.max(Math.abs(ou + r * Math.cos(er) - eu), Math.abs(ov + r * Math.sin(er) - ev));
            if (miss < bestMiss) {
                bestMiss = miss;
                best = GalilNumbers.printedAngle(candidate);
            }
        }
        // The controller holds whole counts: the arc must end nearer the target count than any other.
        if (!(bestMiss < 0.5)) {
            return null;
        }
        delta = best;
        return new Cr(r, start, delta, false);
    }
}
