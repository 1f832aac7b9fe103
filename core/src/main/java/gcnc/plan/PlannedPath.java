package gcnc.plan;

import gcnc.ir.Motion;

/**
 * A straight move or an arc as the planner sees it ({@link Contouring}): its length (counts), its speed limit
 * (counts/s), and its unit directions where it starts and where it ends, in machine counts.
 */
record PlannedPath(boolean rapid, double length, double speed, double entryX, double entryZ, double exitX,
            double exitZ) {
    /** One of {@code n} equal pieces of this straight move. */
    PlannedPath part(int n) {
        return new PlannedPath(rapid, length / n, speed, entryX, entryZ, exitX, exitZ);
    }

    /** A motion of no length after this one: it goes on in this one's direction. */
    PlannedPath standing(double speed) {
        return new PlannedPath(rapid, 0, speed, exitX, exitZ, exitX, exitZ);
    }

    /** The path of a straight move or an arc; null for a dwell or a thread. */
    static PlannedPath of(Motion m, double rapidSpeed, double acceleration) {
        if (m instanceof Motion.Linear l) {
            // between whole counts, as the move is written (VP to the rounded target): a short move's
            // direction is the written one, which the replay checks the corner speeds against (E332)
            double dx = Math.rint(l.to().x()) - Math.rint(l.from().x());
            double dz = Math.rint(l.to().z()) - Math.rint(l.from().z());
            double len = Math.hypot(dx, dz);
            double ux = len == 0 ? 0 : dx / len;
            double uz = len == 0 ? 0 : dz / len;
            return new PlannedPath(l.rapid(), len, l.rapid() ? rapidSpeed : l.feed().countsPerSecond(), ux, uz, ux, uz);
        }
        if (m instanceof Motion.Arc a) {
            double sweep = Math.toRadians(Math.abs(gcnc.ir.ArcGeometry.sweepDegrees(a.from(), a.to(), a.centre(),
                    a.clockwise())));
            double r = a.radius();
            double[] in = tangent(a, a.from());
            double[] out = tangent(a, a.to());
            double speed = Math.min(a.feed().countsPerSecond(), Math.sqrt(acceleration * r));
            return new PlannedPath(false, sweep * r, speed, in[0], in[1], out[0], out[1]);
        }
        return null;
    }

    /**
     * The unit direction of travel at {@code p} on the arc, in machine counts (x, z). The
     * drawing has z to the right and x up, and the arc turns clockwise or not as drawn there.
     */
    private static double[] tangent(Motion.Arc a, gcnc.ir.Point p) {
        double rh = p.z() - a.centre().z();
        double rv = p.x() - a.centre().x();
        double len = Math.hypot(rh, rv);
        if (len == 0) {
            return new double[] {0, 0};
        }
        // counter-clockwise in (h, v) = (-rv, rh); back in (x, z) = (v, h)
        double tx = a.clockwise() ? -rh : rh;
        double tz = a.clockwise() ? rv : -rv;
        return new double[] {tx / len, tz / len};
    }
}
