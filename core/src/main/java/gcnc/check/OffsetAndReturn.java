package gcnc.check;

import gcnc.check.cycle.Move;
import gcnc.check.geom.Coordinates;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * G10 L2 and G30 in the checker's flow. {@link OffsetSetting} and {@link ReferenceReturn} only
 * read the block and return what they found; here the block of its other words is checked and
 * committed, then the work offset is written (G10) or the two rapids are checked and committed
 * (G30), each through the checker.
 */
record OffsetAndReturn(CycleHost host) {

    /**
     * G10 L2: the block of its other words checked and committed, then the offset it writes
     * ({@link OffsetSetting}).
     */
    List<CheckedBlock> setOffset(RawBlock b, Word g, boolean isFirst) {
        CycleBlocks.Split split = OffsetSetting.read(b, g, host.out());
        List<CheckedBlock> done = new ArrayList<>(1);
        if (split.words() == null) {
            return done;
        }
        if (split.passOn() != null) {
            host.one(split.passOn(), isFirst, null).ifPresent(done::add);
        }
        // the checker's coordinate frames, where a G10 L2 writes its work offset
        Coordinates coordinates = host.coordinates();
        OffsetSetting.offset(g, split.words(), host.state(), host.profile(), coordinates, host.out())
                .ifPresent(w -> coordinates.setWork(w.index(), w.at()));
        return done;
    }

    /** G30: the block of its other words, then the two rapids, each checked and committed ({@link ReferenceReturn}). */
    List<CheckedBlock> returnToReference(RawBlock b, Word g, boolean isFirst) {
        CycleBlocks.Split split = ReferenceReturn.read(b, g, host.out());
        List<CheckedBlock> done = new ArrayList<>(3);
        if (split.passOn() != null) {
            host.one(split.passOn(), isFirst, null).ifPresent(done::add);
        }
        if (split.words() == null) {
            return done;
        }
        Optional<Point> ref = ReferenceReturn.reference(g, split.words(), host.profile(), host.out());
        if (ref.isEmpty()) {
            return done;
        }
        ModalState start = host.state();
        Point via = CycleBlocks.target(host, b, split.words().axes(), start);
        if (via == null) {
            return done;
        }
        List<Move> moves = ReferenceReturn.moves(split.words(), ref.get(), via);
        done.addAll(CycleBlocks.write(host, "G" + g.number(), b.line(), g.span(), moves, 1, start, -1, null));
        return done;
    }
}
