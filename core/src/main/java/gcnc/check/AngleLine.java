package gcnc.check;

import gcnc.check.cycle.MoveWriter;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.List;

/**
 * A G01 line given by its angle {@code ,A} and one end coordinate (docs/chamfer.md, "Angles"):
 * Fanuc's direct drawing dimension programming ({@code X2_ ,A_} or {@code Z2_ ,A_}; 0i-TF
 * operator's manual, "Direct drawing dimension programming", T series) and the Haas lathe's
 * {@code ,A} "angle of movement, used with only one of X, Z, U, W" (G01 in the Haas lathe
 * operator's manual). The angle is in degrees from the +Z axis, counterclockwise positive in the
 * Z-right, X-up drawing (toward +X): the Fanuc manual's figures as gcnc's authors read them (its
 * text was not at hand to quote; the Haas entry has no figure and gcnc takes the same convention
 * there); the other coordinate is where the line through the start at
 * that angle meets the one given. The block is then an ordinary G01 to that point, its other
 * words (a ,C or ,R after it) kept, so every check and the corner insertion see the line as the
 * control cuts it.
 *
 * <p>The two-block form ({@code ,A1_} on a block with no end point, the corner found where its
 * line meets the next block's {@code X3_ Z3_ ,A2_}) is {@link #pair}. What is left is E606 (not
 * supported yet): an angle with both end coordinates that no angle-alone block comes before, an
 * angle alone that the next block does not complete (X and Z in absolute with its own ,A), and
 * the angle alone after a held corner block. An angle that never reaches the coordinate given
 * (along the other axis) is E632, two parallel angles E634, Fanuc PS0057 "no solution of block
 * end" as gcnc's authors read the alarm list; an angle on a block that is not a G01 move is E633.
 */
final class AngleLine {
    /** The checker, to look only: this class returns the blocks it resolves and commits nothing. */
    private final Lookahead host;

    AngleLine(Lookahead host) {
        this.host = host;
    }

    /** Whether the block has a ,A this control reads (Haas and Fanuc; the thesis's has no comma words: E604). */
    boolean asks(RawBlock b) {
        if (host.profile().control().corners() == Control.Corners.NONE) {
            return false;
        }
        for (Word w : b.words()) {
            if (w.comma() && w.letter() == Letter.A) {
                return true;
            }
        }
        return false;
    }

    /**
     * The block run from {@code from} with its ,A made into the end coordinate it stands for; after
     * an error reported to {@code out}, the block without the ,A (it runs to the point it names).
     */
    RawBlock resolve(RawBlock b, ModalState from, Diagnostics out) {
        Word angle = null;
        List<Word> without = new ArrayList<>(b.words().size());
        boolean x = false;
        boolean z = false;
        for (Word w : b.words()) {
            if (angle == null && w.comma() && w.letter() == Letter.A) {
                angle = w;
                continue;
            }
            x |= !w.comma() && (w.letter() == Letter.X || w.letter() == Letter.U);
            z |= !w.comma() && (w.letter() == Letter.Z || w.letter() == Letter.W);
            without.add(w);
        }
        RawBlock plain = b.called(without, b.last(), b.depth());
        if (x == z) {
            out.report(b.error(Code.E606_ANGLE_NOT_SUPPORTED_YET, angle.span(), angle, x ? "both X and Z" : "no end point"));
            return plain;
        }
        if (host.startsCycle(plain)) {
            out.report(b.error(Code.E633_ANGLE_NOT_ON_G01, angle.span(), angle));
            return plain;
        }
        Dry dry = host.peek(bare(plain), from, new Diagnostics());
        if (dry == null) {
            return plain; // its own errors are reported when it runs
        }
        Motion.Linear line = CornerWords.feedLine(dry.block().motions());
        if (line == null) {
            out.report(b.error(Code.E633_ANGLE_NOT_ON_G01, angle.span(), angle));
            return plain;
        }
        Units u = dry.next().units();
        double px = host.coordinates().perRadius(u);
        double pz = host.coordinates().perZ(u);
        double a = Math.toRadians(NumberText.decimal(angle.number()));
        double sin = Math.sin(a);
        double cos = Math.cos(a);
        Point p0 = line.from();
        Point p1 = line.to();
        Point end;
        if (x) {
            if (Math.abs(sin) < 1e-9) {
                out.report(b.error(Code.E632_ANGLE_NO_SOLUTION, angle.span(), angle, "X"));
                return plain;
            }
            double dz = (p1.x() - p0.x()) / px * cos / sin;
            end = new Point(p1.x(), p0.z() + dz * pz);
        } else {
            if (Math.abs(cos) < 1e-9) {
                out.report(b.error(Code.E632_ANGLE_NO_SOLUTION, angle.span(), angle, "Z"));
                return plain;
            }
            double dx = (p1.z() - p0.z()) / pz * sin / cos;
            end = new Point(p0.x() + dx * px, p1.z());
        }
        MoveWriter writer = new MoveWriter(CycleBlocks.frame(host.coordinates(), host.profile(), dry.next()), b.line(), angle.span());
        return CornerInsertion.moveTo(plain, writer, end, p0);
    }

    /** Whether the block's ,A stands alone: no end coordinate (X, Z, U, W), the first block of the two-block form. */
    boolean alone(RawBlock b) {
        for (Word w : b.words()) {
            Letter l = w.letter();
            if (!w.comma() && (l == Letter.X || l == Letter.Z || l == Letter.U || l == Letter.W)) {
                return false;
            }
        }
        return asks(b);
    }

    /**
     * The two-block form (Fanuc 0i-TF, direct drawing dimension programming: {@code ,A1_} then
     * {@code X3_ Z3_ ,A2_}): {@code first}, a G01 with ,A alone, ends where its line from its
     * start meets the line through {@code second}'s end at {@code second}'s angle. Both blocks
     * without their ,A, {@code first} given that corner as X and Z (its ,C or ,R kept: the forms
     * {@code ,A1_ ,R1_} and {@code ,A1_ ,C1_}); null when {@code second} does not complete the form
     * (it gives no ,A, or not both X and Z in absolute: the caller reports E606); the two blocks
     * without their ,A after an error reported here (E633, E634).
     */
    RawBlock[] pair(RawBlock first, RawBlock second, ModalState from, Diagnostics out) {
        Word a1 = angle(first);
        Word a2 = angle(second);
        boolean x = false;
        boolean z = false;
        for (Word w : second.words()) {
            x |= !w.comma() && w.letter() == Letter.X;
            z |= !w.comma() && w.letter() == Letter.Z;
            if (!w.comma() && (w.letter() == Letter.U || w.letter() == Letter.W)) {
                return null;
            }
        }
        if (a2 == null || !x || !z || second.malformed() || second.macro() != null) {
            return null;
        }
        RawBlock one = without(first, a1);
        RawBlock two = without(second, a2);
        if (host.startsCycle(one) || host.startsCycle(two)) {
            return null;
        }
        Dry dry1 = host.peek(bare(one), from, new Diagnostics());
        if (dry1 == null) {
            return new RawBlock[] {one, two};
        }
        Dry dry2 = host.peek(bare(two), dry1.next(), new Diagnostics());
        if (dry2 == null || dry2.next().incremental()) {
            return dry2 == null ? new RawBlock[] {one, two} : null;
        }
        Motion.Linear line = CornerWords.feedLine(dry2.block().motions());
        if (line == null || !dry1.block().motions().isEmpty()) {
            out.report(first.error(Code.E633_ANGLE_NOT_ON_G01, a1.span(), a1));
            return new RawBlock[] {one, two};
        }
        Units u = dry2.next().units();
        double px = host.coordinates().perRadius(u);
        double pz = host.coordinates().perZ(u);
        Point s = line.from();
        Point e = line.to();
        double t1 = Math.toRadians(NumberText.decimal(a1.number()));
        double t2 = Math.toRadians(NumberText.decimal(a2.number()));
        // start + t (cos A1, sin A1) = end + v (cos A2, sin A2), in (z, x) with x a radius
        double dz = (e.z() - s.z()) / pz;
        double dx = (e.x() - s.x()) / px;
        double det = Math.sin(t2) * Math.cos(t1) - Math.cos(t2) * Math.sin(t1);
        if (Math.abs(det) < 1e-9) {
            out.report(first.error(Code.E634_ANGLES_PARALLEL, a1.span(), a1, a2, second.line()));
            return new RawBlock[] {one, two};
        }
        double t = (dx * Math.cos(t2) - dz * Math.sin(t2)) / -det;
        Point corner = new Point(s.x() + t * Math.sin(t1) * px, s.z() + t * Math.cos(t1) * pz);
        MoveWriter writer = new MoveWriter(CycleBlocks.frame(host.coordinates(), host.profile(), dry1.next()), first.line(), a1.span());
        return new RawBlock[] {CornerInsertion.moveTo(one, writer, corner, s), two};
    }

    /** The block's first ,A, or null. */
    private static Word angle(RawBlock b) {
        for (Word w : b.words()) {
            if (w.comma() && w.letter() == Letter.A) {
                return w;
            }
        }
        return null;
    }

    private static RawBlock without(RawBlock b, Word w) {
        List<Word> ws = new ArrayList<>(b.words());
        ws.remove(w);
        return b.called(ws, b.last(), b.depth());
    }

    /** The block without its corner words (comma words; C, R, I, K): the line alone, for a dry run. */
    private static RawBlock bare(RawBlock b) {
        List<Word> ws = new ArrayList<>(b.words().size());
        for (Word w : b.words()) {
            Letter l = w.letter();
            if (!w.comma() && l != Letter.C && l != Letter.R && l != Letter.I && l != Letter.K) {
                ws.add(w);
            }
        }
        return b.called(ws, b.last(), b.depth());
    }
}
