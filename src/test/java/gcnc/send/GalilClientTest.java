package gcnc.send;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.Deque;
import org.junit.jupiter.api.Test;

/**
 * The reply deadline of {@link GalilClient}, on a scripted link: a read may return long after the
 * host asked for it (the host was not scheduled), with the reply already there.
 */
class GalilClientTest {
    /** One read of the script: wait this long (ms), then return these bytes ("" : nothing came). */
    private record Step(long sleepMs, String bytes) {
    }

    /** A link that answers each read with the next step, and nothing once the script is out. */
    private static final class Scripted implements Link {
        final Deque<Step> steps = new ArrayDeque<>();
        int reads;

        Scripted then(long sleepMs, String bytes) {
            steps.add(new Step(sleepMs, bytes));
            return this;
        }

        @Override
        public String name() {
            return "scripted";
        }

        @Override
        public void write(byte[] bytes) {
        }

        @Override
        public int read(byte[] into, int timeoutMs) {
            reads++;
            Step s = steps.poll();
            if (s == null) {
                return 0;
            }
            try {
                Thread.sleep(s.sleepMs());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            byte[] b = s.bytes().getBytes(StandardCharsets.ISO_8859_1);
            System.arraycopy(b, 0, into, 0, b.length);
            return b.length;
        }

        @Override
        public void close() {
        }
    }

    @Test
    void aReplyThatCameInTimeIsReadEvenWhenTheHostLooksLate() throws Exception {
        // the first read returns nothing 150 ms after a 100 ms deadline; the reply is there at the next look
        Scripted link = new Scripted().then(150, "").then(0, " 1.0000\r\n:");
        try (GalilClient c = new GalilClient(link, 100, m -> { })) {
            assertEquals(1.0, c.number("_XQ0"), 1e-9); // was: E822 "did not answer in time (nothing)"
        }
    }

    @Test
    void nothingByTheDeadlineIsATimeoutAfterOneLastLook() throws Exception {
        Scripted link = new Scripted().then(150, "");
        try (GalilClient c = new GalilClient(link, 100, m -> { })) {
            LinkFault f = assertThrows(LinkFault.class, () -> c.number("_XQ0"));
            assertEquals(LinkFault.Kind.TIMEOUT, f.kind());
            assertEquals(2, link.reads, "the read that ran past the deadline, then one look");
        }
    }

    @Test
    void bytesThatKeepComingWithoutAnEndDoNotHoldTheDeadlineOpen() throws Exception {
        Scripted link = new Scripted();
        for (int i = 0; i < 1000; i++) {
            link.then(i == 0 ? 150 : 0, "1");
        }
        try (GalilClient c = new GalilClient(link, 100, m -> { })) {
            LinkFault f = assertThrows(LinkFault.class, () -> c.number("_XQ0"));
            assertEquals(LinkFault.Kind.TIMEOUT, f.kind());
            assertTrue(link.reads <= 2, "read " + link.reads + " times past the deadline");
        }
    }
}
