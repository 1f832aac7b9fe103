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
 * chuck M codes), each read on its own and kept when it is well formed and in range. So one bad
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
                    }
                }
            }
        }
        return n.build();
    }

    private static GFunction g(Word w, FunctionIndex functions) {
        return w.number().isEmpty() ? null : functions.g(w.code());
    }

    /** A modal G of a rejected block: its mode, but not its motion (the move was not made). */
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
