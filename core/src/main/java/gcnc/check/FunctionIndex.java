package gcnc.check;

import gcnc.ir.Letter;
import gcnc.machine.Control;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;
import gcnc.tables.ParameterLimit;
import gcnc.tables.Tables;
import java.util.Set;

/**
 * The control's G and M tables and the thesis's Table 6 as arrays, built once, so a block is
 * checked without map look-ups or boxing.
 */
public final class FunctionIndex {
    /** G and M numbers are 0..999 (Haas has G codes above 100). */
    public static final int SIZE = 1000;

    private final Control control;
    private final GFunction[] g = new GFunction[SIZE];
    private final MFunction[] m = new MFunction[SIZE];
    private final GFunction[] byRole = new GFunction[GRole.values().length];
    private final ParameterLimit[] limits = new ParameterLimit[Letter.values().length];
    private final boolean[] letters = new boolean[Letter.values().length];

    public FunctionIndex(Tables tables, Control control) {
        this.control = control;
        for (GFunction f : control.allG()) {
            g[f.code()] = f;
            if (byRole[f.role().ordinal()] == null) {
                byRole[f.role().ordinal()] = f;
            }
        }
        for (MFunction f : control.allM()) {
            m[f.code()] = f;
        }
        for (Letter l : Letter.values()) {
            limits[l.ordinal()] = tables.limit(l.name().charAt(0)).orElse(null);
            letters[l.ordinal()] = control.letters().contains(l);
        }
        for (int code = 0; code < SIZE; code++) {
            if (m[code] == null && control.builderM()) {
                m[code] = new MFunction(code, 0, 0, MRole.OUTPUT, true, "machine-builder M code",
                        "función M del fabricante de la máquina");
            }
        }
    }

    public Control control() {
        return control;
    }

    /** The G function, or null when the control's table has no such code. */
    public GFunction g(long code) {
        return code >= 0 && code < SIZE ? g[(int) code] : null;
    }

    /** The M function, or null when the control has no such code. */
    public MFunction m(long code) {
        return code >= 0 && code < SIZE ? m[(int) code] : null;
    }

    /** Whether the control has a G code that turns tool-nose compensation on (G41/G42). */
    public boolean hasNoseCompensation() {
        return byRole[GRole.NOSE_COMP_LEFT.ordinal()] != null || byRole[GRole.NOSE_COMP_RIGHT.ordinal()] != null;
    }

    /** The control's first G code for a function (the modal motion's code, for messages). */
    public GFunction g(GRole role) {
        return byRole[role.ordinal()];
    }

    /** The Table 6 row of a word, or null when the word has none. */
    public ParameterLimit limit(Letter l) {
        return limits[l.ordinal()];
    }

    /** Whether the control reads this address letter (else E004). */
    public boolean reads(Letter l) {
        return letters[l.ordinal()];
    }

    /** Table 7 for the function with thesis number {@code f}: its parameters, or null when unrestricted. */
    public Set<Tables.Param> allowed(GFunction f) {
        return f == null ? null : f.words();
    }
}
