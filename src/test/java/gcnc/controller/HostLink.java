package gcnc.controller;

import java.io.ByteArrayOutputStream;
import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;

/**
 * The host's side of a link to the virtual controller in the tests: sends a command and reads its reply up
 * to the {@code :} or {@code ?}, keeps every byte it read ({@link #raw}) and the unsolicited ones (high bit
 * set after {@code CW 1}) apart. Reads time out (the stream's own timeout): a reply that never comes fails
 * the test instead of hanging it.
 */
final class HostLink implements Closeable {
    private final InputStream in;
    private final OutputStream out;
    private final Closeable link;
    final ByteArrayOutputStream raw = new ByteArrayOutputStream();
    final StringBuilder unsolicited = new StringBuilder();

    HostLink(InputStream in, OutputStream out, Closeable link) {
        this.in = in;
        this.out = out;
        this.link = link;
    }

    void write(String text) throws IOException {
        out.write(text.getBytes(StandardCharsets.ISO_8859_1));
        out.flush();
    }

    /** One byte of a reply (unsolicited bytes are set aside); -1 at the end of the stream. */
    int read() throws IOException {
        while (true) {
            int b = in.read();
            if (b < 0) {
                return -1;
            }
            raw.write(b);
            if ((b & 0x80) != 0) {
                unsolicited.append((char) (b & 0x7F));
                continue;
            }
            return b;
        }
    }

    /** The reply up to and with its {@code :} or {@code ?}. */
    String reply() throws IOException {
        StringBuilder b = new StringBuilder();
        while (true) {
            int c = read();
            if (c < 0) {
                throw new IOException("the controller closed the link after '" + b + "'");
            }
            b.append((char) c);
            if (c == ':' || c == '?') {
                return b.toString();
            }
        }
    }

    String send(String command) throws IOException {
        write(command + "\r");
        return reply();
    }

    /** The number an interrogation ({@code MG _LMS}) answers. */
    double number(String command) throws IOException {
        String r = send(command);
        if (!r.endsWith(":")) {
            throw new IOException(command + " answered " + r);
        }
        return Double.parseDouble(r.substring(0, r.length() - 1).strip());
    }

    /** DL: the program, then the end marker; the reply ("::" or "?"). */
    String download(String program) throws IOException {
        write("DL\r" + program + "\\");
        String first = reply();
        return first.equals("?") ? first : first + reply();
    }

    /** UL: the program as the controller sends it, before its end marker. */
    String upload() throws IOException {
        write("UL\r");
        StringBuilder b = new StringBuilder();
        while (true) {
            int c = read();
            if (c < 0) {
                throw new IOException("closed during UL");
            }
            if (c == '\\') {
                break;
            }
            b.append((char) c);
        }
        if (read() != ':') {
            throw new IOException("UL did not end with :");
        }
        return b.toString();
    }

    /** Waits until the thread has ended, polling {@code _XQn}; false after {@code seconds}. */
    boolean awaitThreadEnd(int thread, double seconds) throws IOException, InterruptedException {
        long until = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < until) {
            if (number("MG _XQ" + thread) < 0) {
                return true;
            }
            Thread.sleep(10);
        }
        return false;
    }

    @Override
    public void close() throws IOException {
        link.close();
    }
}
