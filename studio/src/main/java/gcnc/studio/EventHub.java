package gcnc.studio;

import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;

/**
 * The studio's server-sent events to every open page: each stream ({@code GET /api/events}) takes a
 * queue of its own and writes what arrives in it. A page that does not read fast enough loses the
 * frames beyond its queue's room (a run's status comes again ten times a second), never the studio's
 * memory or another page's events.
 */
final class EventHub {
    /** Frames a stream may fall behind by before new ones are dropped for it. */
    static final int ROOM = 2000;

    private final Set<BlockingQueue<String>> streams = ConcurrentHashMap.newKeySet();

    /** A new stream's queue; {@link #leave} when the stream ends. */
    BlockingQueue<String> join() {
        BlockingQueue<String> q = new LinkedBlockingQueue<>(ROOM);
        streams.add(q);
        return q;
    }

    void leave(BlockingQueue<String> q) {
        streams.remove(q);
    }

    /** One event to every stream: {@code event: NAME} and its data (one line of JSON). */
    void publish(String event, String data) {
        String frame = "event: " + event + "\ndata: " + data + "\n\n";
        for (BlockingQueue<String> q : streams) {
            q.offer(frame);
        }
    }
}
