package gcnc.ir;

import java.util.List;

/**
 * An unmodifiable copy of a short list made once per block (a line's words, a block's DMC lines).
 * List.copyOf copies the elements twice, into an array and then into the list's own, which showed
 * among the largest allocations of a check; the fixed-arity List.of keeps one array, or none for
 * one or two elements.
 */
public final class ShortLists {
    private ShortLists() {
    }

    public static <T> List<T> copyOf(List<T> in) {
        return switch (in.size()) {
            case 0 -> List.of();
            case 1 -> List.of(in.get(0));
            case 2 -> List.of(in.get(0), in.get(1));
            case 3 -> List.of(in.get(0), in.get(1), in.get(2));
            case 4 -> List.of(in.get(0), in.get(1), in.get(2), in.get(3));
            case 5 -> List.of(in.get(0), in.get(1), in.get(2), in.get(3), in.get(4));
            case 6 -> List.of(in.get(0), in.get(1), in.get(2), in.get(3), in.get(4), in.get(5));
            default -> List.copyOf(in);
        };
    }
}
