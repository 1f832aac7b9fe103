package gcnc.check;

import gcnc.check.cycle.Axes;
import gcnc.check.cycle.Contour;
import gcnc.check.cycle.CycleCall;
import gcnc.check.cycle.FirstBlock;
import gcnc.check.cycle.Fault;
import gcnc.check.cycle.Move;
import gcnc.check.cycle.MoveWriter;
import gcnc.check.cycle.PocketRoughing;
import gcnc.check.cycle.Roughing;
import gcnc.check.geom.Coordinates;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.List;

/**
 * G71 and G72 once their contour is followed: the cycle block's depth, retract and allowances in
 * counts, the passes planned ({@link Roughing}), written as blocks at the cycle's line
 * ({@link MoveWriter}) and checked one by one, each with its pass.
 */
final class StockRemoval {
    /** The most passes one cycle is expanded into. */
    static final int MAX_PASSES = 10_000;
    /** Geometric tolerance, mm. */
    private static final double EPS_MM = 0.001;

    private final Coordinates coordinates;
    private final MachineProfile profile;
    private final Diagnostics out;
    private final CycleCall call;
    private final int line;
    private final Axes axes;

    StockRemoval(Coordinates coordinates, MachineProfile profile, Diagnostics out, CycleCall call, int line) {
        this.coordinates = coordinates;
        this.profile = profile;
        this.out = out;
        this.call = call;
        this.line = line;
        this.axes = call.kind() == GRole.TURNING_CYCLE ? Axes.TURNING : Axes.FACING;
    }

    Axes axes() {
        return axes;
    }

    /**
     * The cycle's passes for the contour followed from {@code start}; empty after a
     * finding. {@code firstBlock}: what a Fanuc first block left in force. {@code lead}: a first
     * contour move the control takes as positioning (Haas, Z alone in a G71's P block), or null.
     */
    java.util.Optional<CycleExpansion.Passes> expand(Contour contour, List<RawBlock> blocks, ModalState start, FirstBlock firstBlock,
                              Contour.Piece lead) {
        Roughing.Settings settings = settings(start, firstBlock);
        if (settings == null) {
            return java.util.Optional.empty();
        }
        boolean two = typeTwo(contour, blocks);
        Roughing.Outcome o = two ? new PocketRoughing(axes, settings).plan(contour) : new Roughing(axes, settings).plan(contour);
        if (o instanceof Fault f && f.code() == Code.E159_CYCLE_ALLOWANCE_SIGN) {
            // the control takes U and W with their signs and roughs into the finished shape (the
            // YASNAC LX3 manual: a wrong sign gouges the workpiece): a warning, and the cycle as written
            report(f, blocks, false);
            Roughing.Settings any = settings.withAnySign();
            o = two ? new PocketRoughing(axes, any).plan(contour) : new Roughing(axes, any).plan(contour);
        }
        if (o instanceof Fault f) {
            report(f, blocks, true);
            return java.util.Optional.empty();
        }
        Roughing.Plan plan = (Roughing.Plan) o;
        List<Move> moves = plan.moves();
        if (lead != null) {
            // Haas: the first move along the cutting axis alone positions the tool at the start's
            // level; the passes start where it ends and the cycle ends back at its start point
            moves = new ArrayList<>(moves.size() + 2);
            moves.add(Move.line(((gcnc.ir.Motion.Linear) lead.motion()).rapid(), contour.start(), 1));
            moves.addAll(plan.moves());
            moves.add(Move.line(true, start.position(), Math.max(1, plan.passes())));
        }
        return java.util.Optional.of(new CycleExpansion.Passes(moves, plan.passes()));
    }

    /**
     * Type II (pockets): Haas {@code R1} on the cycle, or the block of the contour's first move
     * names both axes (X or U, and Z or W; {@code W0} counts), as Fanuc and Haas select it.
     */
    private boolean typeTwo(Contour contour, List<RawBlock> blocks) {
        if (call.typeTwo()) {
            return true;
        }
        for (RawBlock b : blocks) {
            if (b.line() == contour.approach().line()) {
                boolean x = false;
                boolean z = false;
                for (Word w : b.words()) {
                    x |= w.letter() == Letter.X || w.letter() == Letter.U;
                    z |= w.letter() == Letter.Z || w.letter() == Letter.W;
                }
                return x && z;
            }
        }
        return false;
    }

    /** The cycle's allowances, depth and retract in counts; null after E156, E157 or E158. */
    private Roughing.Settings settings(ModalState start, FirstBlock firstBlock) {
        Coordinates c = coordinates;
        MachineProfile p = profile;
        Units u = start.units();
        double depth;
        if (call.has(Letter.D)) {
            depth = call.value(Letter.D);
            if (depth <= 0) {
                out.error(Code.E156_CYCLE_DEPTH, call.words().get(Letter.D).span(), call.name(),
                        call.words().get(Letter.D));
                return null;
            }
        } else if (!Double.isNaN(firstBlock.depth())) {
            depth = firstBlock.depth();
        } else {
            out.error(Code.E157_CYCLE_DEPTH_MISSING, call.g().span(), call.name(),
                    "D, or a " + call.name() + (axes == Axes.TURNING ? " U" : " W") + " R block before it");
            return null;
        }
        double retractMm = Double.isNaN(firstBlock.retractMm()) ? p.control().cycleRetractMm()
                : firstBlock.retractMm();
        if (Double.isNaN(retractMm)) {
            out.error(Code.E157_CYCLE_DEPTH_MISSING, call.g().span(), call.name(),
                    "a " + call.name() + " R block before it, or cycle.retract_mm in the control");
            return null;
        }
        double dx = call.has(Letter.U) ? call.value(Letter.U) * c.perX(u) : 0;
        double dz = call.has(Letter.W) ? call.value(Letter.W) * c.perZ(u) : 0;
        double depthCounts = axes == Axes.TURNING ? depth * c.perRadius(u) : depth * c.perZ(u);
        double perMmDepth = axes == Axes.TURNING ? p.x().countsPerMm() : p.z().countsPerMm();
        double perMmCut = axes == Axes.TURNING ? p.z().countsPerMm() : p.x().countsPerMm();
        return new Roughing.Settings(dx, dz, depthCounts, retractMm * perMmDepth, retractMm * perMmCut,
                EPS_MM * Math.min(p.x().countsPerMm(), p.z().countsPerMm()), MAX_PASSES, p.control().pocketWalls(), false);
    }

    /** Reports why a cycle cannot be expanded, where its fault says. */
    private void report(Fault f, List<RawBlock> blocks, boolean error) {
        List<Object> args = new ArrayList<>();
        args.add(call.name());
        Span at = call.g().span();
        if (f.contourLine() > 0) {
            args.add(line);
            for (RawBlock b : blocks) {
                if (b.line() == f.contourLine()) {
                    at = b.words().isEmpty() ? b.last() : b.words().get(0).span();
                    break;
                }
            }
        } else if (f.word() != null) {
            Word w = call.words().get(f.word());
            if (w != null) {
                at = w.span();
            }
            args.add(w != null ? w : f.word());
        }
        args.addAll(f.args());
        if (error) {
            out.error(f.code(), at, args.toArray());
        } else {
            out.report(gcnc.diag.Diagnostic.warning(f.code(), at, args.toArray()));
        }
    }
}
