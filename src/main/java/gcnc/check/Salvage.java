package gcnc.check;

import gcnc.check.geom.NumberText;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
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
                long s = NumberText.integer(w.number());
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
        return w.number().isEmpty() ? null : functions.g(NumberText.integer(w.number()));
    }

    private static void modalG(GFunction f, ModalState.Next n) {
        if (f == null) {
            return;
        }
        switch (f.role()) {
            case INCH -> n.units = Units.INCH;
            case METRIC -> n.units = Units.MM;
            case FEED_PER_MINUTE, FEED_PER_REV -> n.feedPerRev = f.role() == GRole.FEED_PER_REV;
            case CSS, RPM -> n.css = f.role() == GRole.CSS;
            case ABSOLUTE, INCREMENTAL -> n.incremental = f.role() == GRole.INCREMENTAL;
            case WORK_1, WORK_2, WORK_3, WORK_4, WORK_5, WORK_6 -> n.workOffset = f.role().number();
            default -> {
            }
        }
    }

    private static void spindleOrChuck(Word w, FunctionIndex functions, ModalState.Next n) {
        MFunction f = w.number().isEmpty() ? null : functions.m(NumberText.integer(w.number()));
        if (f == null) {
            n.spindle = ModalState.UNKNOWN;
            n.chuck = ModalState.UNKNOWN;
        } else if (f.role().spindleGroup()) {
            n.spindle = f.role().number();
        } else if (f.role() == MRole.CHUCK_OPEN || f.role() == MRole.CHUCK_CLOSE) {
            n.chuck = f.role().number();
        }
    }

    private static boolean inRange(ParameterLimit lim, double v) {
        return !Double.isNaN(v) && (lim == null || v >= lim.lower() && v <= lim.upper());
    }
}
