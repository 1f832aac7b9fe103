package gcnc.check.geom;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.ArcGeometry;
import gcnc.ir.Feed;
import gcnc.ir.Letter;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.Axis;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import java.util.Optional;

/**
 * G02/G03 with their true geometry (reading §8 [REC], §12.10). R: centre on the chord's
 * perpendicular, R &lt; 0 the long way; an R shorter than half the chord is E101, an R arc ending
 * where it starts E105. I/K: centre = start + (I, K), I a radius even in diameter mode; an end
 * point off that circle by more than {@link #TOLERANCE_MM} is E102. A full circle needs I/K. An arc
 * that bulges out of the travel between its end points is E106.
 */
public final class Arcs {
    /** How far an end point may miss the circle, and R may miss half the chord, in mm. */
    public static final double TOLERANCE_MM = 0.01;

    private final MachineProfile p;
    private final Coordinates c;

    public Arcs(MachineProfile p, Coordinates c) {
        this.p = p;
        this.c = c;
    }

    private double tolerance() {
        return TOLERANCE_MM * p.x().countsPerMm();
    }

    /** The arc, or null after reporting why it cannot be made. */
    public Motion.Arc arc(BlockDraft d, Point from, Point to, Feed feed, Diagnostics out) {
        boolean cw = d.function == 2;
        double tol = tolerance();
        if (d.has(Letter.R)) {
            double r = d.value(Letter.R) * c.perRadius(d.units);
            Span at = d.word(Letter.R).span();
            if (from.distanceTo(to) <= tol) {
                d.fail(out, Code.E105_ARC_FULL_CIRCLE_WITH_R, at);
                return null;
            }
            Optional<Point> centre = ArcGeometry.centreFromRadius(from, to, r, cw, tol);
            if (centre.isEmpty()) {
                double chord = from.distanceTo(to) / c.perRadius(d.units);
                d.fail(out, Code.E101_ARC_RADIUS_TOO_SMALL, at, d.word(Letter.R).number(), text(chord),
                        smallestRadius(chord, r < 0, d.units));
                return null;
            }
            // The radius from the centre, not |R|: an R a little short of half the chord (within the
            // tolerance) puts the centre on the chord, and the arc then has half the chord as radius.
            return inTravel(d, new Motion.Arc(cw, from, to, centre.get(), from.distanceTo(centre.get()), feed,
                    radiusWords(r)), at, out);
        }
        double i = d.has(Letter.I) ? d.value(Letter.I) * c.perRadius(d.units) : 0;
        double k = d.has(Letter.K) ? d.value(Letter.K) * c.perZ(d.units) : 0;
        Point centre = from.plus(i, k);
        double miss = ArcGeometry.endPointError(from, to, centre);
        Span at = d.has(Letter.I) ? d.word(Letter.I).span() : d.word(Letter.K).span();
        if (miss > tol || from.distanceTo(centre) <= tol) {
            d.fail(out, Code.E102_ARC_END_OFF_CIRCLE, at, text(miss / p.x().countsPerMm()), text(TOLERANCE_MM));
            return null;
        }
        return inTravel(d, new Motion.Arc(cw, from, to, centre, from.distanceTo(centre), feed,
                new Motion.ArcWords(null, i, k)), at, out);
    }

    /** The words of an R arc: the last one's while R repeats (a value holding a boxed R, made once). */
    private Motion.ArcWords radiusWords(double r) {
        if (lastRadius == null || Double.compare(lastRadius.r(), r) != 0) {
            lastRadius = new Motion.ArcWords(r, null, null);
        }
        return lastRadius;
    }

    private Motion.ArcWords lastRadius;

    /**
     * The arc, or null after E106 when it bulges out of the travel between its end points (which
     * are inside: the caller checked them). Half a count of slack: less cannot be commanded.
     */
    private Motion.Arc inTravel(BlockDraft d, Motion.Arc a, Span at, Diagnostics out) {
        Axis x = p.x();
        Axis z = p.z();
        Point c = a.centre();
        double r = a.radius();
        if (x.inTravel(c.x() - r) && x.inTravel(c.x() + r) && z.inTravel(c.z() - r) && z.inTravel(c.z() + r)) {
            return a; // the whole circle is inside: no need to find where the arc turns (most arcs)
        }
        double[] b = ArcGeometry.bounds(a);
        if (b[0] < x.min() - 0.5 || b[1] > x.max() + 0.5) {
            beyond(d, "X", b[0] < x.min() - 0.5 ? b[0] : b[1], x, at, out);
            return null;
        }
        if (b[2] < z.min() - 0.5 || b[3] > z.max() + 0.5) {
            beyond(d, "Z", b[2] < z.min() - 0.5 ? b[2] : b[3], z, at, out);
            return null;
        }
        return a;
    }

    private static void beyond(BlockDraft d, String axis, double counts, Axis a, Span at, Diagnostics out) {
        double perMm = a.countsPerMm();
        d.fail(out, Code.E106_ARC_BEYOND_TRAVEL, at, axis, text(counts / perMm), text(a.min() / perMm),
                text(a.max() / perMm));
    }

    /**
     * The R that just spans a chord (half of it), as a word's number: rounded up to the units'
     * last digit (0.001 mm, 0.0001 in) so that the R shown is long enough, with a decimal point
     * (on a Fanuc-style control R15 would be 0.015 mm), and the sign of the R written (the long way
     * round stays the long way).
     */
    static String smallestRadius(double chord, boolean negative, Units u) {
        double scale = u == Units.INCH ? 1e4 : 1e3;
        String r = NumberText.plain(Math.ceil(chord / 2 * scale - 1e-6) / scale);
        return (negative ? "-" : "") + (NumberText.hasPoint(r) ? r : r + ".");
    }

    /** A length or speed for a message, to 0.001, as a person writes it (30.414, 60000; never 6.0E4). */
    static String text(double v) {
        return NumberText.plain(v, 3);
    }
}
