package gcnc.dmc;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * {@link CommandKind} has one constant for each command, and each command finds its own: the switches
 * over the kind are exhaustive only if no two commands share a kind and none is left without one.
 */
class CommandKindTest {
    @Test
    void everyCommandHasItsOwnKind() throws ReflectiveOperationException {
        List<Command> all = gcnc.SealedSamples.oneOfEach(Command.class);
        Map<CommandKind, String> seen = new EnumMap<>(CommandKind.class);
        for (Command c : all) {
            CommandKind k = CommandKind.of(c);
            String before = seen.put(k, c.getClass().getSimpleName());
            assertEquals(null, before, k + " is the kind of both " + before + " and " + c.getClass().getSimpleName());
            // one name for one thing: the kind is the record's name in upper snake case
            assertEquals(c.getClass().getSimpleName().replaceAll("(?<=[a-z])(?=[A-Z])", "_").toUpperCase(), k.name());
        }
        assertEquals(CommandKind.values().length, all.size(), "a kind no command has: " + seen.keySet());
    }

    @Test
    void aSequenceIsReadByItsParts() {
        assertEquals(SequencePart.SPEED, SequencePart.of(new Command.VectorSpeed(Fixed.of(100))));
        assertEquals(SequencePart.SEGMENT, SequencePart.of(new Command.VectorPosition(1, 2)));
        assertEquals(SequencePart.SEGMENT, SequencePart.of(new Command.CircularArc(Fixed.of(1), Fixed.of(0), Fixed.of(90))));
        assertEquals(SequencePart.VECTOR_END, SequencePart.of(new Command.VectorEnd()));
        assertEquals(SequencePart.BEGIN, SequencePart.of(new Command.BeginSequence()));
        assertEquals(SequencePart.ROOM_WAIT, SequencePart.of(new Command.Call(StreamSplit.BUFFER_WAIT)));
        assertEquals(SequencePart.NONE, SequencePart.of(new Command.Call(ProgramStop.LABEL)));
        assertEquals(SequencePart.TRIP, SequencePart.of(new Command.AfterVector(10)));
        assertEquals(SequencePart.AWAIT, SequencePart.of(new Command.AwaitSequence()));
        assertEquals(SequencePart.OUTSIDE, SequencePart.of(new Command.AfterMotion("XY")));
        assertEquals(SequencePart.OUTSIDE, SequencePart.of(new Command.End()));
        assertEquals(SequencePart.NONE, SequencePart.of(new Command.Output(1, true)));
    }
}
