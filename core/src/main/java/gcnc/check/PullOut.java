package gcnc.check;

import gcnc.machine.ThreadChamfer;

/**
 * How a pass of a G76 or G92 thread ends while Haas M23 is in force (docs/threading.md): with the
 * profile's chamfer, X moving out toward {@code side} (+1 or -1, machine X counts: the side of the
 * thread the cycle's start point is on).
 */
public record PullOut(ThreadChamfer chamfer, int side) {
    public PullOut {
        if (side != 1 && side != -1) {
            throw new IllegalArgumentException("a pull-out goes out along +X or -X, not " + side);
        }
    }
}
