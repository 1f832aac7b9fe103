package gcnc.controller;

/**
 * The operands of the virtual controller, {@code _NAME} in an expression: what the motion ({@code _LMS},
 * {@code _CSS}, {@code _AVS}, {@code _BGS}, {@code _TPX} ...), the error ({@code _TC}, {@code _ED}), the memory
 * ({@code _DL}, {@code _UL}, {@code _DA}, {@code _DM}), the ports ({@code _CF}, {@code _EO}), the threads
 * ({@code _XQn}) and the axes' settings read now. {@link VirtualGalil} answers {@link Expressions.Scope#operand}
 * with them.
 */
final class Operands {
    private Operands() {
    }

    /** The array elements the arrays of {@code c} take up ({@code DM}). */
    static int elementsUsed(VirtualGalil c) {
        int elements = 0;
        for (double[] a : c.arrays.values()) {
            elements += a.length;
        }
        return elements;
    }

    /** The operand {@code _name} of controller {@code c}; TC 1 for a name it does not have. */
    static double read(VirtualGalil c, String name) throws GalilException {
        VectorMotion mo = c.motion;
        switch (name) {
            case "LMS": return mo.free();
            case "CSS": return mo.css();
            case "AVS": return Math.floor(mo.travelled()); // the path run since the sequence began (AV's distance)
            case "BGS": return mo.running() ? 1 : 0;
            case "SCS": return mo.stopCode;
            case "VRS": return mo.vr;
            case "VSS": return mo.vs;
            case "TC": return c.lastError.code;
            case "ED": return c.errorLine;
            case "ED1": return c.errorThread;
            case "DL": return c.model.labels - c.program.labelCount();
            case "UL": return c.model.variables - c.variables.size();
            case "DA": return Model.ARRAYS - c.arrays.size();
            case "DM": return c.model.arrayElements - elementsUsed(c);
            case "CF": return c.cf; // "the decimal value of the ASCII letter" (COMALL CF)
            case "EO": return c.echo ? 1 : 0;
            default: break;
        }
        if (name.length() == 3 && name.startsWith("XQ") && Character.isDigit(name.charAt(2))) {
            int n = name.charAt(2) - '0';
            if (n > 7) {
                throw new GalilException(Tc.OPERAND);
            }
            return c.threads[n].running() ? c.threads[n].line : -1;
        }
        if (name.length() == 3) {
            int a = c.axis(name.charAt(2));
            if (a >= 0) {
                switch (name.substring(0, 2)) {
                    case "TP", "RP": return Math.rint(mo.position[a]);
                    case "GR": return c.gearing.ratio[a]; // as GR set it, at its resolution 1/65,536
                    case "VP": return mo.corner(a);
                    case "BG": return mo.running() && (a == mo.axis1 || a == mo.axis2) || c.gearing.moving[a] ? 1 : 0;
                    case "SC": return a == mo.axis1 || a == mo.axis2 ? mo.stopCode : 1;
                    case "MO": return c.servo[a] ? 0 : 1;
                    case "OF": return c.offsets[a];
                    case "IT": return c.smoothing[a];
                    // limit inputs are active low: 0 while the switch is tripped
                    case "LF": return c.limitTripped && a == mo.axis1 ? 0 : 1;
                    case "LR": return 1;
                    case "HM": return 1; // the home input, inactive: no homing is modelled
                    default: break;
                }
            }
        }
        throw new GalilException(Tc.UNRECOGNIZED);
    }
}
