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
import gcnc.machine.MachineProfile;
import java.util.Optional;

/**
 * G02/G03 with their true geometry (reading §8 [REC], §12.10). R: centre on the chord's
 * perpendicular, R &lt; 0 the long way; an R shorter than half the chord is E101, an R arc ending
 * where it starts E105. I/K: centre = start + (I, K), I a radius even in diameter mode; an end
 * point off that circle by more than {@link #TOLERANCE_MM} is E102. A full circle needs I/K.
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
                d.fail(out, Code.E101_ARC_RADIUS_TOO_SMALL, at, d.word(Letter.R).number(),
                        round(from.distanceTo(to) / c.perRadius(d.units)));
                return null;
            }
            // The radius from the centre, not |R|: an R a little short of half the chord (within the
            // tolerance) puts the centre on the chord, and the arc then has half the chord as radius.
            return new Motion.Arc(cw, from, to, centre.get(), from.distanceTo(centre.get()), feed,
                    new Motion.ArcWords(r, null, null));
        }
        double i = d.has(Letter.I) ? d.value(Letter.I) * c.perRadius(d.units) : 0;
        double k = d.has(Letter.K) ? d.value(Letter.K) * c.perZ(d.units) : 0;
        Point centre = from.plus(i, k);
        double miss = ArcGeometry.endPointError(from, to, centre);
        Span at = d.has(Letter.I) ? d.word(Letter.I).span() : d.word(Letter.K).span();
        if (miss > tol || from.distanceTo(centre) <= tol) {
            d.fail(out, Code.E102_ARC_END_OFF_CIRCLE, at, round(miss / p.x().countsPerMm()), TOLERANCE_MM);
            return null;
        }
        return new Motion.Arc(cw, from, to, centre, from.distanceTo(centre), feed, new Motion.ArcWords(null, i, k));
    }

    static double round(double v) {
        return Math.round(v * 1000) / 1000.0;
    }
}
