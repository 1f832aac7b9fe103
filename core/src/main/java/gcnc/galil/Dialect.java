package gcnc.galil;

import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.machine.MachineProfile;

/**
 * A DMC code generator (docs/dmc-format.md): checked blocks in, {@link gcnc.dmc.Instruction}s out,
 * each with the block it came from; text is made only at the edge ({@link gcnc.dmc.DmcPrinter}).
 * One instance per program: it keeps the controller's position between blocks. Faults in the output (a count beyond 32 bits, an arc no CR can draw)
 * are reported to {@link Diagnostics} at the block's line, column 1; the faulty motion is left out.
 */
public interface Dialect {
    /** Writes what comes before the first block. */
    void begin(java.util.function.Consumer<gcnc.dmc.Instruction> out);

    /**
     * Records the blank the program was verified against when the program or the user gave one
     * (a stock header, {@code --stock}), or that there was none ({@code blank} empty: {@code
     * --stock none}), so that a replay of the DMC by itself cuts the same blank. Called after
     * {@link #begin}; a dialect that reproduces an old format writes nothing.
     */
    void blank(java.util.Optional<gcnc.machine.MachineModel.Blank> blank, java.util.function.Consumer<gcnc.dmc.Instruction> out);

    /** Writes one planned step (docs/galil.md): a block's setup, its motions alone or joined, its end. */
    void lower(gcnc.plan.Step step, java.util.function.Consumer<gcnc.dmc.Instruction> out);

    /** Writes one block's directives, in the order of decision D2, each motion stopped at its end. */
    default void block(CheckedBlock block, java.util.function.Consumer<gcnc.dmc.Instruction> out) {
        new gcnc.plan.ExactStop().accept(block, step -> lower(step, out));
    }

    /** Writes what comes after the last block. */
    void end(java.util.function.Consumer<gcnc.dmc.Instruction> out);

    /** The dialects gcnc writes, parsed once where the user names them ({@code --dialect galil|thesis}). */
    enum Kind {
        /** A standalone DMC program a controller can run (the default). */
        GALIL,
        /** The thesis's directives, reproducing its Table 5.2 byte for byte. */
        THESIS;

        /** The name the user writes: {@code galil} or {@code thesis}. */
        public String label() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }

        /**
         * The dialect called {@code name} ({@code galil} or {@code thesis}).
         *
         * @throws IllegalArgumentException for an unknown dialect name
         */
        public static Kind of(String name) {
            for (Kind k : values()) {
                if (k.label().equals(name)) {
                    return k;
                }
            }
            throw new IllegalArgumentException("unknown dialect '" + name + "' (galil or thesis)");
        }
    }

    /** The dialect {@code kind}, without inline source-map comments. */
    static Dialect create(Kind kind, MachineProfile profile, Diagnostics diagnostics) {
        return create(kind, profile, diagnostics, false);
    }

    /**
     * @param inlineSourceMap put a {@code NO L<line>} comment before each block's lines
     *                        ({@code --source-map}); otherwise use a {@link SourceMap} side file
     */
    static Dialect create(Kind kind, MachineProfile profile, Diagnostics diagnostics, boolean inlineSourceMap) {
        switch (kind) {
            case GALIL:
                return new GalilDialect(profile, diagnostics, inlineSourceMap);
            case THESIS:
                return new ThesisDialect(profile, diagnostics, inlineSourceMap);
            default:
                throw new IllegalStateException("a dialect with no code generator: " + kind);
        }
    }
}
