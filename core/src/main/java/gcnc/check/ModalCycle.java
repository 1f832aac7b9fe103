package gcnc.check;

import gcnc.ir.RawBlock;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import java.util.function.Predicate;

/**
 * A modal cycle in force (G90/G94, G32/G92, G81-G83): which one, its G group and its name as the
 * program wrote it. A block with an axis word and no G that ends it runs it again; a G of its group
 * (and whatever else {@code alsoEnds} says) ends it.
 */
final class ModalCycle {
    private final Predicate<GFunction> alsoEnds;
    private GRole kind;
    private int group;
    private String name;

    /** A cycle that only a G of its own group ends. */
    ModalCycle() {
        this(f -> false);
    }

    /** A cycle that a G of its own group or one {@code alsoEnds} accepts ends (G00/G01 end a drilling cycle). */
    ModalCycle(Predicate<GFunction> alsoEnds) {
        this.alsoEnds = alsoEnds;
    }

    /** The cycle in force, or null. */
    GRole kind() {
        return kind;
    }

    /** The cycle in force as the program wrote it ("G92"), for a finding about running it again. */
    String name() {
        return name;
    }

    void start(GRole kind, GFunction g, String name) {
        this.kind = kind;
        this.group = g.group();
        this.name = name;
    }

    void end() {
        kind = null;
    }

    private boolean endedBy(GFunction f) {
        return f.group() == group || alsoEnds.test(f);
    }

    /** Whether the block runs the cycle in force again: an axis word, no G that ends it and no one-shot G. */
    boolean repeats(CycleHost host, RawBlock b) {
        return kind != null && CycleBlocks.repeats(host, b, this::endedBy);
    }

    /** An ordinary block: a G that ends the cycle ends it. */
    void note(CycleHost host, RawBlock b) {
        if (kind != null && CycleBlocks.ends(host, b, this::endedBy)) {
            kind = null;
        }
    }
}
