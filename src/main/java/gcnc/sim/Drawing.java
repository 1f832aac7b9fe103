package gcnc.sim;

import java.util.List;

/**
 * Everything the SVG writer draws, in the half-section (z, r) in machine millimetres
 * (r = radius from the spindle centreline). Kept only when an SVG is asked for.
 *
 * @param chuck       chuck outlines
 * @param tailstock   tailstock outlines
 * @param stockBack   z where the blank starts (inside the chuck)
 * @param stockFace   z of the blank's face
 * @param stockRadius initial radius, NaN when there is no stock
 * @param finalZ      final part profile: cell centres
 * @param finalR      final part profile: radii
 * @param moves       the tool path, one polyline per sequence
 * @param marks       where findings were reported
 */
public record Drawing(List<Shape> chuck, List<Shape> tailstock, double stockBack, double stockFace,
                      double stockRadius, double[] finalZ, double[] finalR, List<Move> moves, List<Mark> marks) {
    /** One sequence of the path as a polyline; rapid ones are drawn dashed. */
    public record Move(boolean rapid, double[] z, double[] r) {
    }

    /** A finding at a place: its code (E305 ...) and the point. */
    public record Mark(String code, double z, double r) {
    }
}
