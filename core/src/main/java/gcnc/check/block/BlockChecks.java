package gcnc.check.block;

import java.util.List;

/**
 * The end-of-block operations in the order they run, declared here and nowhere else. The
 * thesis's {@code ChkParameters} order (reading §6): two functions with parameters (op 5) before
 * the function is chosen and its Table 7 words checked (op 1), then sufficient parameters (op 4),
 * G29 after G28 (op 3), G28's point (op 2), the S operations (6, 7) and cutting prerequisites (8).
 */
public final class BlockChecks {
    public static final List<BlockCheck> ORDER = List.of(new Eb05SingleParameterFunction(),
            new Eb01ParameterOwner(), new Eb04EnoughParameters(), new Eb03G29NeedsG28(), new Eb02G28Point(),
            new Eb06SpindleClamp(), new Eb07SpindleSpeed(), new Eb08CuttingPrerequisites());

    private BlockChecks() {
    }
}
