package gcnc.flow;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Each outcome of a macro line names its own {@link MacroLine.Outcome.Kind}, and every kind is some outcome's. */
class OutcomeKindTest {
    @Test
    void everyOutcomeHasItsOwnKind() throws ReflectiveOperationException {
        List<MacroLine.Outcome> all = gcnc.SealedSamples.oneOfEach(MacroLine.Outcome.class);
        Map<MacroLine.Outcome.Kind, String> seen = new EnumMap<>(MacroLine.Outcome.Kind.class);
        for (MacroLine.Outcome o : all) {
            String name = o.getClass().getSimpleName();
            assertEquals(null, seen.put(o.kind(), name), o.kind() + " is the kind of two outcomes");
            assertEquals(name.replaceAll("(?<=[a-z])(?=[A-Z])", "_").toUpperCase(), o.kind().name());
        }
        assertEquals(MacroLine.Outcome.Kind.values().length, all.size(), "a kind no outcome has: " + seen.keySet());
    }
}
