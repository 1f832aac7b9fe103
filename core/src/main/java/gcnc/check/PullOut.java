package gcnc.check;

import gcnc.machine.ThreadChamfer;

/**
 * How a pass of a G76 or G92 thread ends with a chamfer (docs/threading.md): with {@code chamfer},
 * X moving out toward {@code side} (+1 or -1, machine X counts: the side of the thread the cycle's
 * start point is on). Haas: the profile's chamfer while M23 is in force. Fanuc: the G76 chamfer rr.
 */
public record PullOut(ThreadChamfer chamfer, int side) {
    public PullOut {
        if (side != 1 && side != -1) {
            throw new IllegalArgumentException("a pull-out goes out along +X or -X, not " + side);
        }
    }

    /**
     * A Fanuc G76 pass's chamfer: {@code tenths} of a lead (the rr of {@code G76 P(mmrraa)},
     * parameter 5130, 00 to 99) at the machine's chamfer angle ({@code thread.chamfer_angle},
     * which is parameter 5131 on a Fanuc: 45 degrees when that parameter is 0); null for rr = 00,
     * a straight pull-out.
     */
    static PullOut fanuc(int tenths, ThreadChamfer machine, int side) {
        return tenths == 0 ? null : new PullOut(new ThreadChamfer(tenths / 10.0, machine.angle()), side);
    }
}
