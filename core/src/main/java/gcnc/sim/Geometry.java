package gcnc.sim;

/**
 * Exact 2-D test the collision checks need. A convex tool shape swept along a straight move is
 * the Minkowski sum of the shape and the move; it overlaps a convex obstacle unless some axis
 * separates them (separating axis theorem). The candidate axes are the edge normals of both
 * shapes and the normal of the move. Touching (overlap below {@code slack} counts) is allowed.
 * No allocation: this runs per segment.
 */
final class Geometry {
    private Geometry() {
    }

    /**
     * Length of (dx, dz). Math.hypot guards against overflow we cannot have (counts stay far below
     * 1e150) at many times the cost of a square root, and the simulator asks this per segment.
     */
    static double length(double dx, double dz) {
        return Math.sqrt(dx * dx + dz * dz);
    }

    /** Does {@code tool} (relative to the tip) moved from tip a to tip b overlap {@code obstacle}? */
    static boolean sweptHits(Shape tool, double az, double ar, double bz, double br, Shape obstacle, double slack) {
        double dz = bz - az;
        double dr = br - ar;
        if (separatedByEdges(tool, tool, az, ar, dz, dr, obstacle, slack)
                || separatedByEdges(obstacle, tool, az, ar, dz, dr, obstacle, slack)) {
            return false;
        }
        double len = length(dz, dr);
        return len == 0 || !separatedOn(-dr / len, dz / len, tool, az, ar, dz, dr, obstacle, slack);
    }

    private static boolean separatedByEdges(Shape edges, Shape tool, double az, double ar, double dz, double dr,
                                            Shape obstacle, double slack) {
        int n = edges.size();
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double nz = edges.r()[j] - edges.r()[i];
            double nr = -(edges.z()[j] - edges.z()[i]);
            double len = length(nz, nr);
            if (len > 0 && separatedOn(nz / len, nr / len, tool, az, ar, dz, dr, obstacle, slack)) {
                return true;
            }
        }
        return false;
    }

    private static boolean separatedOn(double nz, double nr, Shape tool, double az, double ar, double dz, double dr,
                                       Shape obstacle, double slack) {
        double tMin = Double.MAX_VALUE;
        double tMax = -Double.MAX_VALUE;
        for (int i = 0; i < tool.size(); i++) {
            double p = (tool.z()[i] + az) * nz + (tool.r()[i] + ar) * nr;
            tMin = Math.min(tMin, p);
            tMax = Math.max(tMax, p);
        }
        double move = dz * nz + dr * nr;
        tMin += Math.min(0, move);
        tMax += Math.max(0, move);
        double oMin = Double.MAX_VALUE;
        double oMax = -Double.MAX_VALUE;
        for (int i = 0; i < obstacle.size(); i++) {
            double p = obstacle.z()[i] * nz + obstacle.r()[i] * nr;
            oMin = Math.min(oMin, p);
            oMax = Math.max(oMax, p);
        }
        return Math.max(oMin - tMax, tMin - oMax) >= -slack;
    }
}
