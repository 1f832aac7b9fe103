package gcnc.check;

import gcnc.check.geom.NumberText;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MFunction;
import gcnc.machine.MachineProfile;
import gcnc.tables.ParameterLimit;

/**
 * What a rejected block still sets: its modal words whose meaning does not depend on the rest of
 * the block (units, feed mode, F, S, CSS on/off, absolute/incremental, work offset, spindle and
 * chuck M codes, its motion G when it has only one), each read on its own and kept when it is well
 * formed and in range; and when only its move failed, the end point ({@link #moved}). So one bad
 * word on a safe-start line does not leave an inch program checked in millimetres, and a rejected
 * {@code G99 ... F0.2} does not make every later cut report a missing feed.
 *
 * <p>A block with an M word gcnc could not read (M93 typed for M03) might have started the
 * spindle or moved the chuck: their state becomes unknown, so later cuts are not blamed for it
 * (E051, E037, E038 wait for the next spindle or chuck M).
 */
final class Salvage {
    private Salvage() {
    }

    static ModalState keep(RawBlock b, ModalState prior, FunctionIndex functions, MachineProfile profile) {
        ModalState.Next n = prior.next();
        boolean clampBlock = false;
        for (Word w : b.words()) {
            if (w.letter() == Letter.G && g(w, functions) != null
                    && g(w, functions).role() == GRole.REGISTER_AND_CLAMP) {
                clampBlock = true;
            }
        }
        GFunction motion = null;
        int motions = 0;
        for (Word w : b.words()) {
            GFunction f = w.letter() == Letter.G ? g(w, functions) : null;
            if (f != null && f.role().motion()) {
                motion = f;
                motions++;
            }
        }
        if (motions == 1) {
            // one motion G: what the block meant is not in doubt, and the control would be in that
            // mode once the operator fixed the block (two are E016: neither is kept)
            n.set(motion.role());
        }
        for (Word w : b.words()) {
            switch (w.letter()) {
                case G -> modalG(g(w, functions), n);
                case M -> spindleOrChuck(w, functions, n);
                case F -> {
                    double f = NumberText.decimal(w.number());
                    if (inRange(functions.limit(Letter.F), f)) {
                        n.feed = f;
                    }
                }
                default -> {
                }
            }
        }
        for (Word w : b.words()) {
            if (w.letter() == Letter.S) {
                long s = w.code();
                if (s != NumberText.NOT_INTEGER && inRange(functions.limit(Letter.S), s)) {
                    if (clampBlock) {
                        n.rpmClamp = s;
                    } else if (n.css) {
                        n.surfaceSpeed = s;
                    } else if (s <= profile.maxRpm() && !(s > n.rpmClamp)) {
                        n.rpm = s;
                    } else if (s > n.rpmClamp && n.rpmClamp <= profile.maxRpm() && functions.control().clampAboveLimit()) {
                        n.rpm = n.rpmClamp; // E280: the control turns at the limit
                    }
                }
            }
        }
        return n.build();
    }

    /**
     * A block whose words and checks passed but whose move could not be made (E015 travel, an arc
     * that does not close): what {@link #keep} keeps, and its motion G and end point too, so that the
     * next {@code X80.} is read under this block's G01, from here, as the control would read it once
     * the operator fixed this block's end point (an axis the block took beyond the travel stays).
     */
    static ModalState moved(RawBlock b, ModalState prior, BlockDraft d, FunctionIndex functions,
                            MachineProfile profile) {
        ModalState.Next n = keep(b, prior, functions, profile).next();
        n.motion = d.next.motion;
        if (d.function >= 0 && d.function <= 3) {
            // an axis beyond the travel stays where it was: the fixed end point is not known, and
            // keeping the rejected one would make every later move report the same travel (E015)
            gcnc.ir.Point to = d.coordinates.target(d, prior.position());
            gcnc.ir.Point from = prior.position();
            n.position = new gcnc.ir.Point(profile.x().inTravel(to.x()) ? to.x() : from.x(),
                    profile.z().inTravel(to.z()) ? to.z() : from.z());
        }
        return n.build();
    }

    private static GFunction g(Word w, FunctionIndex functions) {
        return w.number().isEmpty() ? null : functions.g(w.code());
    }

    /** A modal G of a rejected block other than its motion G (kept above when it is the only one). */
    private static void modalG(GFunction f, ModalState.Next n) {
        if (f != null && !f.role().motion()) {
            n.set(f.role());
        }
    }

    private static void spindleOrChuck(Word w, FunctionIndex functions, ModalState.Next n) {
        MFunction f = w.number().isEmpty() ? null : functions.m(w.code());
        if (f == null) {
            n.spindle = ModalState.UNKNOWN;
            n.chuck = ModalState.UNKNOWN;
        } else {
            n.set(f.role());
        }
    }

    private static boolean inRange(ParameterLimit lim, double v) {
        return !Double.isNaN(v) && (lim == null || v >= lim.lower() && v <= lim.upper());
    }
}
