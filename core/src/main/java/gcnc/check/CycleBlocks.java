package gcnc.check;

import gcnc.check.cycle.Move;
import gcnc.check.cycle.MoveWriter;
import gcnc.check.geom.Coordinates;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * What the expanded cycles (G74, G75, G81-G83, G90/G94, G32/G92) share: the G function a word
 * names, whether a later block makes a modal cycle run again, the words of other functions taken
 * out of the cycle block and made a block of their own, the end point resolved like a move's, and
 * the moves written as blocks at the cycle's line and checked one by one, each with its pass.
 */
final class CycleBlocks {
    private CycleBlocks() {
    }

    /** The G function a G word names in the control, or null (another letter, no number, no such G). */
    static gcnc.machine.GFunction function(CycleHost host, Word w) {
        if (w.letter() != Letter.G || w.number().isEmpty() || w.code() < 0 || w.code() > 999) {
            return null;
        }
        return host.functions().g((int) w.code());
    }

    /**
     * Whether a block makes the modal cycle in force run again: it has an axis word (X, U, Z or W),
     * and no G that {@code ends} the cycle nor a one-shot G (group 0: G04 U1., G28 U0, G50 X), whose
     * words those would be.
     */
    static boolean repeats(CycleHost host, RawBlock b, Predicate<gcnc.machine.GFunction> ends) {
        boolean axis = false;
        for (Word w : b.words()) {
            gcnc.machine.GFunction f = function(host, w);
            if (f != null && (ends.test(f) || f.group() == 0)) {
                return false;
            }
            Letter l = w.letter();
            axis |= l == Letter.X || l == Letter.U || l == Letter.Z || l == Letter.W;
        }
        return axis;
    }

    /** Whether a G of the block ends the modal cycle in force, as {@code ends} says. */
    static boolean ends(CycleHost host, RawBlock b, Predicate<gcnc.machine.GFunction> ends) {
        for (Word w : b.words()) {
            gcnc.machine.GFunction f = function(host, w);
            if (f != null && ends.test(f)) {
                return true;
            }
        }
        return false;
    }

    /** The block's N, F, S, T, M and non-cycle G words (when its cycle words could not be read). */
    static List<Word> passOn(RawBlock b, Word g, Predicate<Word> isCycle) {
        List<Word> kept = new ArrayList<>();
        for (Word w : b.words()) {
            boolean other = switch (w.letter()) {
                case N, F, S, T, M -> true;
                case G -> w != g && !isCycle.test(w);
                default -> false;
            };
            if (other) {
                kept.add(w);
            }
        }
        return kept;
    }

    /**
     * A block split as G10 and G30 read it: the words of other functions as a block of their own
     * (null when none), and the function's words (null after their error).
     */
    record Split(RawBlock passOn, gcnc.check.cycle.CycleWords words) {
    }

    /**
     * The block split as G10 and G30 read it ({@code g} the function's word, {@code own} the letters
     * it reads); an error in its words to {@code out}.
     */
    static Split split(RawBlock b, Word g, java.util.Set<Letter> own, Diagnostics out) {
        gcnc.check.cycle.CycleWords words = gcnc.check.cycle.CycleWords.read(b, g, "G" + g.number(), own, own, 1, 1,
                w -> false, out);
        return new Split(passOnBlock(b, words != null ? words.passOn() : List.of()), words);
    }

    /** The block's G word of the function with {@code role} (G10 L2, G30), or null. */
    static Word gWord(RawBlock b, FunctionIndex functions, GRole role) {
        List<Word> ws = b.words();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            Word w = ws.get(at);
            if (w.letter() == Letter.G && !w.number().isEmpty()) {
                gcnc.machine.GFunction f = functions.g(w.code());
                if (f != null && f.role() == role) {
                    return w;
                }
            }
        }
        return null;
    }

    /** The words of other functions as a block of their own at the block's line, or null when none. */
    static RawBlock passOnBlock(RawBlock b, List<Word> passOn) {
        if (passOn.isEmpty()) {
            return null;
        }
        return new RawBlock(b.line(), passOn, passOn.get(passOn.size() - 1).span(), false, b.blockDelete());
    }

    /** The words of other functions as a block of their own, checked and committed; empty when none. */
    static Optional<CheckedBlock> passOn(CycleHost host, RawBlock b, List<Word> passOn, boolean isFirst) {
        RawBlock block = passOnBlock(b, passOn);
        return block == null ? Optional.empty() : host.one(block, isFirst, null);
    }

    /** Where the block's axis words lead from {@code start} (a rapid followed aside), or null after its error. */
    static Point target(CycleHost host, RawBlock b, List<Word> axes, ModalState start) {
        if (axes.isEmpty()) {
            return start.position();
        }
        List<Word> words = new ArrayList<>(axes.size() + 1);
        String rapid = host.profile().control().gFor(GRole.RAPID).map(f -> f.name().substring(1)).orElseThrow();
        words.add(new Word(Letter.G, rapid, axes.get(0).span()));
        words.addAll(axes);
        Diagnostics found = new Diagnostics();
        Dry dry = host.dry(new RawBlock(b.line(), words, words.get(words.size() - 1).span(), false), start,
                found);
        host.out().addAll(found);
        return dry == null ? null : dry.block().end();
    }

    /**
     * The moves as blocks at the cycle's line, each checked, labelled "G75 pass 2 of 3" for the
     * simulator's findings; {@code dwell} (when not null) is checked right after move
     * {@code dwellAfter}. After the first that fails, a rapid back to the start ends the cycle.
     */
    static List<CheckedBlock> write(CycleHost host, String name, int line, Span at, List<Move> moves, int passes,
                                    ModalState start, int dwellAfter, RawBlock dwell) {
        return write(host, name, line, at, moves, passes, start,
                dwell == null ? java.util.Map.of() : java.util.Map.of(dwellAfter, List.of(dwell)));
    }

    /**
     * The moves as blocks, as above, with the blocks of {@code after} checked right after the move
     * of their index (a dwell at a hole's bottom, a tap's spindle reversal).
     */
    static List<CheckedBlock> write(CycleHost host, String name, int line, Span at, List<Move> moves, int passes,
                                    ModalState start, java.util.Map<Integer, List<RawBlock>> after) {
        return write(host, new MoveWriter(frame(host, start), line, at), moves, start, after,
                pass -> new CycleOrigin(name, pass, passes, line, -1, -1, false));
    }

    /** The program frame a cycle's moves are written in: the state's work zero, units and G91. */
    static MoveWriter.Frame frame(CycleHost host, ModalState s) {
        return frame(host.coordinates(), host.profile(), s);
    }

    /** As above, from the checker's coordinates and profile. */
    static MoveWriter.Frame frame(Coordinates c, gcnc.machine.MachineProfile profile, ModalState s) {
        Units u = s.units();
        List<String> codes = new ArrayList<>(4);
        for (GRole r : new GRole[] {GRole.RAPID, GRole.LINEAR, GRole.ARC_CW, GRole.ARC_CCW}) {
            codes.add(profile.control().gFor(r).map(f -> f.name().substring(1)).orElseThrow());
        }
        return new MoveWriter.Frame(c.origin(s.next()), c.perX(u), c.perRadius(u), c.perZ(u), s.incremental(), codes);
    }

    /**
     * The moves as blocks at the cycle's line, each checked. After the first that fails the cycle
     * is not followed further: a rapid back to the start point ends it, so that the blocks after
     * the cycle are judged from where the cycle leaves the tool (one finding, not one per pass).
     */
    static List<CheckedBlock> write(CycleHost host, gcnc.check.cycle.CycleCall call, int line, List<Move> moves, int passes,
                                    ModalState start) {
        long p = call.label(Letter.P);
        long q = call.label(Letter.Q);
        return write(host, new MoveWriter(frame(host, start), line, call.g().span()), moves, start, java.util.Map.of(),
                pass -> new CycleOrigin(call.name(), pass, passes, line, p, q, false));
    }

    /** The loop of both writes above: {@code origins} labels the blocks of each pass. */
    private static List<CheckedBlock> write(CycleHost host, MoveWriter writer, List<Move> moves, ModalState start,
                                            java.util.Map<Integer, List<RawBlock>> after,
                                            java.util.function.IntFunction<CycleOrigin> origins) {
        List<CheckedBlock> done = new ArrayList<>();
        Point from = start.position();
        for (int i = 0; i < moves.size(); i++) {
            Move m = moves.get(i);
            CycleOrigin origin = origins.apply(m.pass());
            Optional<CheckedBlock> r = host.one(writer.block(m, from), false, origin);
            for (RawBlock extra : after.getOrDefault(i, List.of())) {
                if (r.isEmpty()) {
                    break;
                }
                done.add(r.get());
                r = host.one(extra, false, origin);
            }
            if (r.isEmpty()) {
                abandon(host, writer, start.position(), origin).ifPresent(done::add);
                break;
            }
            done.add(r.get());
            from = host.state().position();
        }
        return done;
    }

    /** After a move of a cycle failed: a rapid from where the checker left the tool to the cycle's end point. */
    static Optional<CheckedBlock> abandon(CycleHost host, MoveWriter writer, Point end, CycleOrigin origin) {
        Point at = host.state().position();
        if (at.distanceTo(end) <= 1e-9) {
            return Optional.empty();
        }
        return host.one(writer.block(Move.line(true, end, origin.pass()), at), false, origin);
    }
}
