package gcnc.check;

import gcnc.check.cycle.Move;
import gcnc.check.cycle.MoveWriter;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Writes a thread cycle's planned moves (G92, G76) as blocks and hands each to the checker: the
 * rapids as G00 blocks, the passes as G01 blocks checked as threads.
 */
final class ThreadPassWriter {
    private final CycleHost host;

    ThreadPassWriter(CycleHost host) {
        this.host = host;
    }

    /**
     * The moves as blocks at the cycle's line: rapids as G00 blocks, the thread passes as G01
     * blocks with the lead as F, checked as threads, ending with {@code pullOut}'s chamfer when it
     * is not null (Haas M23). After one fails, a rapid back to the start ends the cycle
     * ({@link CycleExpansion#abandon}).
     */
    void write(List<CheckedBlock> done, int line, Span at, ModalState start, List<Move> moves, double lead,
                       String label, java.util.function.IntFunction<CycleOrigin> origins, PullOut pullOut,
                       double startAngle) {
        MoveWriter writer = new MoveWriter(CycleBlocks.frame(host, start), line, at);
        Point a = start.position();
        Point from = a;
        Word f = new Word(Letter.F, MoveWriter.number(lead), at);
        for (Move m : moves) {
            if (m.to().distanceTo(from) <= 1e-9) {
                continue;
            }
            CycleOrigin origin = origins.apply(m.pass());
            RawBlock block = writer.block(m, from);
            Optional<CheckedBlock> r;
            if (m.kind() == Move.Kind.FEED) {
                List<Word> ws = new ArrayList<>(block.words());
                ws.add(f);
                r = host.thread(new RawBlock(line, ws, at, false), false, origin, label, pullOut, startAngle);
            } else {
                r = host.one(block, false, origin);
            }
            if (r.isEmpty()) {
                CycleBlocks.abandon(host, writer, a, origin).ifPresent(done::add);
                break;
            }
            done.add(r.get());
            from = host.state().position();
        }
    }
}
