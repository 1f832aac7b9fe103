package gcnc.output;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;

/**
 * Lines into a stream through gcnc's own buffer ({@link AtomicOutput#line}): no lock and no copy
 * per line, numbers written digit by digit (a compile writes millions of lines). The first write
 * failure is kept ({@link #failure}) and every line after it dropped, so that the output's commit
 * throws it instead of putting a half-written file in place.
 */
final class LineBuffer {
    private final OutputStream out;
    private final byte[] buffer = new byte[1 << 16];
    private int buffered;
    /** The first write error, or null. */
    private IOException failure;

    LineBuffer(OutputStream out) {
        this.out = out;
    }

    /** The first write error, or null. */
    IOException failure() {
        return failure;
    }

    /** What is buffered into the stream, unless a write failed already. */
    void flush() throws IOException {
        if (failure == null) {
            drain();
        }
    }

    /**
     * Writes one line with an LF end (decision D5: files use LF; the sender sends CR). The line is
     * encoded by the String itself (a copy for ASCII text) and copied into the buffer: a loop over
     * its characters here was a tenth of a long compile's main thread.
     */
    void line(String text) {
        if (failure != null) {
            return;
        }
        try {
            int n = text.length();
            if (n < ASCII_DIRECT) {
                // a DMC line is short ASCII: its chars are its bytes, copied without an array per line
                if (buffered + n + 1 > buffer.length) {
                    drain();
                }
                int start = buffered;
                int i = 0;
                for (char c; i < n && (c = text.charAt(i)) < 0x80; i++) {
                    buffer[buffered++] = (byte) c;
                }
                if (i == n) {
                    buffer[buffered++] = '\n';
                    return;
                }
                buffered = start; // not ASCII: encoded below
            }
            byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
            if (buffered + bytes.length + 1 > buffer.length) {
                drain();
            }
            if (bytes.length + 1 > buffer.length) {
                out.write(bytes);
                out.write('\n');
                return;
            }
            System.arraycopy(bytes, 0, buffer, buffered, bytes.length);
            buffered += bytes.length;
            buffer[buffered++] = '\n';
        } catch (IOException e) {
            failure = e;
        }
    }

    /** Lines shorter than this are copied char by char while they are ASCII. */
    private static final int ASCII_DIRECT = 256;

    /** "{@code a.k b}", or "{@code a b}" when {@code k} is 0: a map entry that starts inside a packed line. */
    void line(long a, int k, long b) {
        if (failure != null) {
            return;
        }
        try {
            if (buffered + 54 > buffer.length) {
                drain();
            }
            digits(a);
            if (k != 0) {
                buffer[buffered++] = '.';
                digits(k);
            }
            buffer[buffered++] = ' ';
            digits(b);
            buffer[buffered++] = '\n';
        } catch (IOException e) {
            failure = e;
        }
    }

    private void digits(long v) {
        if (v < 0) {
            buffer[buffered++] = '-';
            if (v == Long.MIN_VALUE) {
                byte[] rest = Long.toString(v).substring(1).getBytes(StandardCharsets.US_ASCII);
                System.arraycopy(rest, 0, buffer, buffered, rest.length);
                buffered += rest.length;
                return;
            }
            v = -v;
        }
        int start = buffered;
        do {
            buffer[buffered++] = (byte) ('0' + v % 10);
            v /= 10;
        } while (v > 0);
        for (int i = start, j = buffered - 1; i < j; i++, j--) {
            byte t = buffer[i];
            buffer[i] = buffer[j];
            buffer[j] = t;
        }
    }

    private void drain() throws IOException {
        out.write(buffer, 0, buffered);
        buffered = 0;
    }
}
