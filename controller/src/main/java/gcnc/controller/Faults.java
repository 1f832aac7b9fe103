package gcnc.controller;

import java.util.List;

/**
 * The link faults of a run ({@code --fault}), with the counters they fire on: bytes sent and received and
 * commands answered over the controller's whole life, across connections. Each fires once. The segment
 * faults (stall, limit) are the motion's: {@link VirtualGalil} arms them.
 */
final class Faults {
    /** The bytes a {@code garbage-after} fault sends: no {@code :}, {@code ?}, CR or LF, no high bit. */
    static final byte[] GARBAGE = {0x15, '~', '#', 'Z', 'q', '%', 0x07, 0x00, '{', 'x'};

    private long garbageAfter = -1;
    private long reject = -1;
    private long disconnectAfter = -1;
    final long slowMillis;
    /** An {@code echo-ethernet} fault: the Ethernet handles echo what they receive, against the reference. */
    final boolean echoEthernet;
    private long sent;
    private long received;
    private long commands;

    Faults(List<InjectedFault> faults) {
        long slow = 0;
        boolean echo = false;
        for (InjectedFault f : faults) {
            switch (f.kind()) {
                case GARBAGE_AFTER -> garbageAfter = f.n();
                case REJECT -> reject = f.n();
                case DISCONNECT_AFTER -> disconnectAfter = f.n();
                case SLOW -> slow = f.n();
                case ECHO_ETHERNET -> echo = f.n() != 0;
                default -> {
                }
            }
        }
        slowMillis = slow;
        echoEthernet = echo;
    }

    /**
     * {@code n} bytes are about to be sent: where in them the garbage goes (0..n), or -1 when not now.
     */
    synchronized int garbageAt(int n) {
        int at = -1;
        if (garbageAfter >= 0 && sent + n >= garbageAfter) {
            at = (int) (garbageAfter - sent);
            garbageAfter = -1;
        }
        sent += n;
        return at;
    }

    /** One byte was received: true when the connection must now be closed. */
    synchronized boolean received() {
        received++;
        if (disconnectAfter >= 0 && received >= disconnectAfter) {
            disconnectAfter = -1;
            return true;
        }
        return false;
    }

    /** A command is about to be executed: true when it is the one to answer {@code ?}. */
    synchronized boolean reject() {
        commands++;
        if (commands == reject) {
            reject = -1;
            return true;
        }
        return false;
    }
}
