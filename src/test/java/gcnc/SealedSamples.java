package gcnc;

import java.lang.reflect.Constructor;
import java.lang.reflect.RecordComponent;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * One value of each record a sealed interface permits, its components at plain values: for the tests
 * that every member names its own kind (the switches over a kind are exhaustive only if it does).
 */
public final class SealedSamples {
    private SealedSamples() {
    }

    /** One instance of each permitted record of {@code sealed}, in declaration order. */
    public static <T> List<T> oneOfEach(Class<T> sealed) throws ReflectiveOperationException {
        List<T> all = new ArrayList<>();
        for (Class<?> record : sealed.getPermittedSubclasses()) {
            RecordComponent[] parts = record.getRecordComponents();
            Class<?>[] types = new Class<?>[parts.length];
            Object[] values = new Object[parts.length];
            for (int i = 0; i < parts.length; i++) {
                types[i] = parts[i].getType();
                values[i] = plain(types[i]);
            }
            Constructor<?> canonical = record.getDeclaredConstructor(types);
            canonical.setAccessible(true);
            all.add(sealed.cast(canonical.newInstance(values)));
        }
        return all;
    }

    /** A plain value of {@code type}: 1, "A", an empty optional or list, a record's or enum's first value. */
    private static Object plain(Class<?> type) {
        if (type == int.class) {
            return 1;
        }
        if (type == long.class) {
            return 1L;
        }
        if (type == double.class) {
            return 1.0;
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
        if (type == Optional.class) {
            return Optional.empty();
        }
        if (type == List.class) {
            return List.of();
        }
        if (type.isEnum()) {
            return type.getEnumConstants()[0];
        }
        if (type == gcnc.dmc.Fixed.class) {
            return gcnc.dmc.Fixed.of(1);
        }
        if (type == gcnc.dmc.Command.Speeds.class) {
            return gcnc.dmc.Command.Speeds.NONE;
        }
        return null; // an array, a span, an operand: not read by a kind
    }
}
