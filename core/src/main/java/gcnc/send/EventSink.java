package gcnc.send;

/** Where a run's events go: the status line, the JSON stream, a test's list. */
@FunctionalInterface
public interface EventSink {
    void accept(Event e);
}
