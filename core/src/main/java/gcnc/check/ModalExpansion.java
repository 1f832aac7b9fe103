package gcnc.check;

import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import java.util.List;

/**
 * A cycle modal in its group (G90/G94 {@link SingleCycle}, G32/G92/G76 {@link Threading}, G81-G89
 * {@link HoleDrilling}): the cycle in force ({@link ModalCycle}), whether a block makes it again,
 * what ends it, and the name and role a block's cycle is run as. Each subclass expands its blocks.
 */
abstract class ModalExpansion {
    final CycleHost host;
    /** The cycle in force, if any: its name, group and what ends it. */
    final ModalCycle modal;

    ModalExpansion(CycleHost host, ModalCycle modal) {
        this.host = host;
        this.modal = modal;
    }

    final GFunction function(Word w) {
        return CycleBlocks.function(host, w);
    }

    /**
     * A G word beside the cycle's own: handed on (into {@code passOn}) unless it is the G of a cycle
     * or a thread, which takes the block's axis words too and is foreign here (E161). Returns the
     * block's first foreign word: {@code foreign}, else this G when it is one.
     */
    final Word otherG(Word w, List<Word> passOn, Word foreign) {
        GFunction f = function(w);
        if (f != null && (f.role().singleCycle() || f.role().contourCycle() || f.role().thread())) {
            return foreign == null ? w : foreign;
        }
        passOn.add(w);
        return foreign;
    }

    /** The cycle in force as the program wrote it ("G90"), for a finding about running it again. */
    final String name() {
        return modal.name();
    }

    /** Whether the block makes the cycle in force again: an axis word and no G that ends it or owns the words. */
    final boolean repeats(RawBlock b) {
        return modal.repeats(host, b);
    }

    /** An ordinary block: a G that ends the cycle in force ends it. */
    void note(RawBlock b) {
        modal.note(host, b);
    }

    /** The role of the block's cycle word {@code g}, or of the cycle in force for a block that makes it again (g null). */
    final GRole role(Word g) {
        return g == null ? modal.kind() : function(g).role();
    }

    /** The cycle's name for the block's findings ("G92"): its word's, or the cycle in force's (g null). */
    final String label(Word g) {
        return g == null ? modal.name() : "G" + g.number();
    }

    /** A block with the cycle's word {@code g}, or one that makes the cycle in force again (g null): its blocks. */
    abstract List<CheckedBlock> run(RawBlock b, Word g, boolean isFirst);
}
