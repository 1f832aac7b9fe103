package gcnc.lsp;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.LinkedBlockingDeque;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The two ends of the protocol's byte streams, guarded so that no client can stop the server: a
 * message longer than the input limit is skipped as it arrives (read and dropped, never held whole
 * in memory), and the output is a queue drained by a thread of its own, so that a client that does
 * not read what it is sent never blocks the checker; past the output limit, messages are dropped
 * (each drop logged) until the client reads again. LSP4J reads and writes the messages themselves.
 */
final class Framing {
    private Framing() {
    }

    /** The input, one {@code Content-Length} frame at a time: a frame over {@code limit} bytes is skipped and logged. */
    static final class GuardedInput extends InputStream {
        private static final Pattern LENGTH = Pattern.compile("(?im)^content-length:\\s*(\\d{1,18})\\s*$");
        /** The most header bytes looked at before a frame's body. */
        private static final int HEADER_LIMIT = 8192;
        private final InputStream in;
        private final long limit;
        private final Log log;
        /** Header bytes read and not yet handed on. */
        private byte[] header = new byte[0];
        private int headerAt;
        /** Body bytes of the current frame still to hand on. */
        private long body;

        GuardedInput(InputStream in, long limit, Log log) {
            this.in = in;
            this.limit = limit;
            this.log = log;
        }

        @Override
        public int read() throws IOException {
            byte[] one = new byte[1];
            int n = read(one, 0, 1);
            return n < 0 ? -1 : one[0] & 0xff;
        }

        @Override
        public int read(byte[] b, int off, int len) throws IOException {
            if (len == 0) {
                return 0;
            }
            while (headerAt >= header.length && body == 0) {
                if (!nextFrame()) {
                    return -1;
                }
            }
            if (headerAt < header.length) {
                int n = Math.min(len, header.length - headerAt);
                System.arraycopy(header, headerAt, b, off, n);
                headerAt += n;
                return n;
            }
            int n = in.read(b, off, (int) Math.min(len, body));
            if (n > 0) {
                body -= n;
            }
            return n;
        }

        /** Reads the next frame's header; false at the end of the input. */
        private boolean nextFrame() throws IOException {
            ByteArrayOutputStream h = new ByteArrayOutputStream();
            int c;
            int state = 0; // how much of "\r\n\r\n" was just read
            while ((c = in.read()) >= 0) {
                h.write(c);
                state = c == '\n' && (state == 1 || state == 3) ? state + 1 : c == '\r' && (state == 0 || state == 2) ? state + 1
                        : c == '\r' ? 1 : 0;
                if (state == 4 || h.size() >= HEADER_LIMIT) {
                    break;
                }
            }
            if (h.size() == 0) {
                return false;
            }
            byte[] bytes = h.toByteArray();
            Matcher m = LENGTH.matcher(new String(bytes, StandardCharsets.US_ASCII));
            long length = state == 4 && m.find() ? Long.parseLong(m.group(1)) : -1;
            if (length > limit) {
                log.error("a message of " + length + " bytes is more than the " + limit
                        + " this server reads: skipped (a buffer that large is not checked here; use gcnc check)");
                byte[] skip = new byte[1 << 16];
                for (long left = length; left > 0; ) {
                    int n = in.read(skip, 0, (int) Math.min(skip.length, left)); // read, not skip(): a pipe cannot seek
                    if (n < 0) {
                        return false;
                    }
                    left -= n;
                }
                header = new byte[0];
                headerAt = 0;
                return true;
            }
            header = bytes;
            headerAt = 0;
            body = Math.max(0, length);
            return true;
        }
    }

    /**
     * The output: each message LSP4J writes (it flushes once per message) goes on a queue that a
     * thread writes to {@code out}; past {@code limit} bytes waiting, a message is dropped and logged.
     */
    static final class QueuedOutput extends OutputStream {
        private final LinkedBlockingDeque<byte[]> queue = new LinkedBlockingDeque<>();
        private final Object lock = new Object();
        private final long limit;
        private final Log log;
        private ByteArrayOutputStream current = new ByteArrayOutputStream();
        private long waiting;
        private long dropped;
        private volatile boolean failed;
        private final Thread writer;

        QueuedOutput(OutputStream out, long limit, Log log) {
            this.limit = limit;
            this.log = log;
            writer = new Thread(() -> drainTo(out), "gcnc-lsp-output");
            writer.setDaemon(true);
            writer.start();
        }

        private void drainTo(OutputStream out) {
            try {
                while (true) {
                    byte[] m = queue.take();
                    out.write(m);
                    out.flush();
                    synchronized (lock) {
                        waiting -= m.length;
                        lock.notifyAll();
                    }
                }
            } catch (IOException e) {
                failed = true;
                log.error("cannot write to the client: " + e.getMessage());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        @Override
        public void write(int b) {
            current.write(b);
        }

        @Override
        public void write(byte[] b, int off, int len) {
            current.write(b, off, len);
        }

        @Override
        public void flush() {
            byte[] m = current.toByteArray();
            current = new ByteArrayOutputStream();
            if (m.length == 0 || failed) {
                return;
            }
            synchronized (lock) {
                if (waiting + m.length > limit) {
                    dropped++;
                    log.error("the client has not read " + waiting + " bytes of this server's output: a message of "
                            + m.length + " bytes dropped (" + dropped + " so far)");
                    return;
                }
                waiting += m.length;
            }
            queue.add(m);
        }

        /** Waits up to {@code millis} for the client to have been sent everything queued. */
        void drain(long millis) throws InterruptedException {
            long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
            synchronized (lock) {
                while (waiting > 0 && !failed) {
                    long left = TimeUnit.NANOSECONDS.toMillis(end - System.nanoTime());
                    if (left <= 0) {
                        return;
                    }
                    lock.wait(left);
                }
            }
        }
    }
}
