package gcnc.check.block;

import java.util.ArrayList;
import java.util.List;

/**
 * The end-of-block operations by their thesis numbers and in the order they run, declared here and
 * nowhere else. The thesis's {@code ChkParameters} order (reading §6): two functions with parameters
 * (op 5) before the function is chosen and its Table 7 words checked (op 1), then sufficient
 * parameters (op 4), G29 after G28 (op 3), G28's point (op 2), the S operations (6, 7) and cutting
 * prerequisites (8).
 */
public final class BlockChecks {
    /** The operations by number, 1..8, the number in each class's name; index 0 unused. */
    private static final BlockCheck[] BY_NUMBER = {null, new Eb01ParameterOwner(), new Eb02G28Point(),
        new Eb03G29NeedsG28(), new Eb04EnoughParameters(), new Eb05SingleParameterFunction(),
        new Eb06SpindleClamp(), new Eb07SpindleSpeed(), new Eb08CuttingPrerequisites()};

    /** The operations' numbers in the order they run (above). */
    private static final int[] RUN_ORDER = {5, 1, 4, 3, 2, 6, 7, 8};

    public static final List<BlockCheck> ORDER = inOrder();

    private BlockChecks() {
    }

    /** The operation of number n (1..8). */
    public static BlockCheck check(int n) {
        return BY_NUMBER[n];
    }

    private static List<BlockCheck> inOrder() {
        List<BlockCheck> order = new ArrayList<>(RUN_ORDER.length);
        for (int n : RUN_ORDER) {
            order.add(BY_NUMBER[n]);
        }
        return List.copyOf(order);
    }
}
