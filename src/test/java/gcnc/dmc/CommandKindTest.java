package gcnc.dmc;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.reflect.Constructor;
import java.lang.reflect.RecordComponent;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * {@link CommandKind} has one constant for each command, and each command finds its own: the switches
 * over the kind are exhaustive only if no two commands share a kind and none is left without one.
 */
class CommandKindTest {
    /** One command of each record {@link Command} permits, its components at plain values. */
    private static List<Command> everyCommand() throws ReflectiveOperationException {
        List<Command> all = new ArrayList<>();
        for (Class<?> record : Command.class.getPermittedSubclasses()) {
            RecordComponent[] parts = record.getRecordComponents();
            Class<?>[] types = new Class<?>[parts.length];
            Object[] values = new Object[parts.length];
            for (int i = 0; i < parts.length; i++) {
                types[i] = parts[i].getType();
                values[i] = plain(types[i]);
            }
            Constructor<?> canonical = record.getDeclaredConstructor(types);
            all.add((Command) canonical.newInstance(values));
        }
        return all;
    }

    private static Object plain(Class<?> type) {
        if (type == int.class) {
            return 1;
        }
        if (type == long.class) {
            return 1L;
        }
        if (type == char.class) {
            return 'X';
        }
        if (type == boolean.class) {
            return true;
        }
        if (type == String.class) {
            return "A";
        }
        if (type == Fixed.class) {
            return Fixed.of(1);
        }
        if (type == Optional.class) {
            return Optional.empty();
        }
        if (type == List.class) {
            return List.of();
        }
        if (type == Command.Speeds.class) {
            return Command.Speeds.NONE;
        }
        if (type == Command.Setting.class) {
            return Command.Setting.KP;
        }
        return null; // a stop's reason, an operand: not read by the kind
    }

    @Test
    void everyCommandHasItsOwnKind() throws ReflectiveOperationException {
        List<Command> all = everyCommand();
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
