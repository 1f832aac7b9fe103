package gcnc.controller;

import java.util.Locale;

/**
 * A fault the virtual controller injects on demand ({@code --fault KIND=N}); each fires at most once. Byte
 * counts run over the controller's whole life, across connections; commands and segments are counted
 * from 1 (docs/virtual-controller.md, "Faults").
 */
public record InjectedFault(Kind kind, long n) {
    /** The kinds, by their name on the command line. */
    public enum Kind {
        /** After N bytes sent to the host, a burst of bytes that are no Galil reply. */
        GARBAGE_AFTER,
        /** The N-th command from the host is answered {@code ?} and not executed. */
        REJECT,
        /** The connection is closed once N bytes have been received from the host. */
        DISCONNECT_AFTER,
        /** Every reply waits N milliseconds (real time) before it is sent. */
        SLOW,
        /**
         * Every statement of a program thread takes N milliseconds of controller time (Galil decodes one in
         * about 0.05 ms; counted as VirtualGalil counts the 20 a millisecond, a line's end a step too): a program too slow to keep a sequence fed while it runs, as the slow host is in the
         * stream form.
         */
        SLOW_THREAD,
        /** The profiler stops taking segments from the buffer after segment N: the motion halts there. */
        STALL,
        /** A limit switch trips half way through segment N: decelerating stop, #LIMSWI if the program has it. */
        LIMIT_AT,
        /**
         * With N = 1, the Ethernet handles echo every byte they receive, as a unit that contradicts the
         * reference ("The ethernet port will not echo commands", COMALL EO) would: for the probe's tests.
         */
        ECHO_ETHERNET;

        String spelling() {
            return name().toLowerCase(Locale.ROOT).replace('_', '-');
        }
    }

    /** {@code kind=N} as on the command line; IllegalArgumentException naming the accepted forms. */
    public static InjectedFault parse(String spec) {
        int eq = spec.indexOf('=');
        String name = eq < 0 ? spec : spec.substring(0, eq);
        Kind kind = null;
        for (Kind k : Kind.values()) {
            if (k.spelling().equals(name.strip().toLowerCase(Locale.ROOT))) {
                kind = k;
            }
        }
        long n = -1;
        try {
            n = eq < 0 ? -1 : Long.parseLong(spec.substring(eq + 1).strip());
        } catch (NumberFormatException e) {
            n = -1;
        }
        if (kind == null || n < (kind == Kind.GARBAGE_AFTER || kind == Kind.DISCONNECT_AFTER || kind == Kind.SLOW ? 0 : 1)
                || kind == Kind.ECHO_ETHERNET && n != 1) {
            throw new IllegalArgumentException("'" + spec + "' is not a fault: give one of garbage-after=BYTES,"
                    + " reject=COMMAND, disconnect-after=BYTES, slow=MS, slow-thread=MS, stall=SEGMENT, limit-at=SEGMENT, echo-ethernet=1"
                    + " (commands and segments counted from 1)");
        }
        return new InjectedFault(kind, n);
    }

    @Override
    public String toString() {
        return kind.spelling() + "=" + n;
    }
}
