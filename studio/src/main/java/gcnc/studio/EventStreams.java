package gcnc.studio;

import com.sun.net.httpserver.HttpExchange;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The studio's event streams ({@code GET /api/events}, docs/studio.md): the list of programs as it
 * changes, a run's events from the {@link EventHub}, a comment in quiet times; a few at once, each
 * holding one of the server's threads, all closed when the studio stops.
 */
final class EventStreams implements AutoCloseable {
    /** Each stream holds one of the server's threads: a few pages, and the rest keep answering. */
    static final int MAX_STREAMS = 3;

    /** The list of programs as {@code GET /api/files} answers it, as JSON text. */
    interface FileList {
        String files(HttpExchange ex) throws IOException;
    }

    /** The open event streams, closed when the studio stops. */
    private final Set<OutputStream> streams = ConcurrentHashMap.newKeySet();
    /** What the event streams carry besides the list of files: a run's events. */
    private final EventHub hub;
    private final FileList list;
    private volatile boolean closed;

    EventStreams(EventHub hub, FileList list) {
        this.hub = hub;
        this.list = list;
    }

    /**
     * GET /api/events: server-sent events. {@code files} whenever the list of programs changes
     * (a program made or removed outside the studio), so the page's list stays true; {@code run} for
     * each event of a run (docs/studio.md, "Run"); a comment every ten seconds of quiet keeps the
     * stream open. The page's EventSource reconnects by itself.
     */
    void serve(HttpExchange ex) throws IOException, Http.Fail {
        if (streams.size() >= MAX_STREAMS) {
            throw new Http.Fail(503, "too many event streams open (" + MAX_STREAMS + "); close another studio tab");
        }
        ex.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
        ex.getResponseHeaders().set("Cache-Control", "no-store");
        ex.sendResponseHeaders(200, 0);
        OutputStream out = ex.getResponseBody();
        streams.add(out);
        java.util.concurrent.BlockingQueue<String> queue = hub.join();
        try {
            String last = null;
            long nextList = 0;
            long quietSince = System.nanoTime();
            while (!closed) {
                long now = System.nanoTime();
                if (now >= nextList) {
                    // the folder is looked at once a second
                    String files = list.files(ex);
                    if (!files.equals(last)) {
                        out.write(("event: files\ndata: " + files + "\n\n").getBytes(StandardCharsets.UTF_8));
                        last = files;
                        quietSince = now;
                    } else if (now - quietSince > 10_000_000_000L) {
                        out.write(": still here\n\n".getBytes(StandardCharsets.UTF_8));
                        quietSince = now;
                    }
                    out.flush();
                    nextList = now + 1_000_000_000L;
                }
                String frame = queue.poll(Math.max(1, (nextList - System.nanoTime()) / 1_000_000), java.util.concurrent.TimeUnit.MILLISECONDS);
                if (frame != null) {
                    // what has come meanwhile goes in one write
                    StringBuilder b = new StringBuilder(frame);
                    for (String more = queue.poll(); more != null && b.length() < 1 << 16; more = queue.poll()) {
                        b.append(more);
                    }
                    out.write(b.toString().getBytes(StandardCharsets.UTF_8));
                    out.flush();
                    quietSince = System.nanoTime();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            hub.leave(queue);
            streams.remove(out);
        }
    }

    /** Every stream ends its loop (at its next wake, within a second). */
    void stop() {
        closed = true;
    }

    @Override
    public void close() {
        closed = true;
        for (OutputStream s : List.copyOf(streams)) {
            try {
                s.close();
            } catch (IOException e) {
                // already gone
            }
        }
    }
}
