package gcnc.send;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Each event names its own {@link Event.Kind}, the kind of its record's name, and every kind is some event's. */
class EventKindTest {
    @Test
    void everyEventHasItsOwnKind() throws ReflectiveOperationException {
        List<Event> all = gcnc.SealedSamples.oneOfEach(Event.class);
        Map<Event.Kind, String> seen = new EnumMap<>(Event.Kind.class);
        for (Event e : all) {
            String name = e.getClass().getSimpleName();
            assertEquals(null, seen.put(e.kind(), name), e.kind() + " is the kind of two events");
            assertEquals(name.replaceAll("(?<=[a-z])(?=[A-Z])", "_").toUpperCase(), e.kind().name());
        }
        assertEquals(Event.Kind.values().length, all.size(), "a kind no event has: " + seen.keySet());
    }
}
