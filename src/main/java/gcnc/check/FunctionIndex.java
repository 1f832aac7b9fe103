package gcnc.check;

import gcnc.ir.Letter;
import gcnc.tables.GFunction;
import gcnc.tables.MFunction;
import gcnc.tables.ParameterLimit;
import gcnc.tables.Tables;

/** Tables 3, 4 and 6 as arrays, built once, so a block is checked without map look-ups or boxing. */
public final class FunctionIndex {
    /** G and M numbers of the tables are two digits (Tables 3 and 4). */
    public static final int SIZE = 100;

    private final GFunction[] g = new GFunction[SIZE];
    private final MFunction[] m = new MFunction[SIZE];
    private final ParameterLimit[] limits = new ParameterLimit[Letter.values().length];
    @SuppressWarnings("unchecked")
    private final java.util.Set<Tables.Param>[] usage = new java.util.Set[SIZE];

    public FunctionIndex(Tables tables) {
        for (GFunction f : tables.allG()) {
            if (f.code() >= 0 && f.code() < SIZE) {
                g[f.code()] = f;
            }
        }
        for (MFunction f : tables.allM()) {
            if (f.code() >= 0 && f.code() < SIZE) {
                m[f.code()] = f;
            }
        }
        for (int f = 0; f < SIZE; f++) {
            usage[f] = tables.allowedParameters(f).orElse(null);
        }
        for (Letter l : Letter.values()) {
            limits[l.ordinal()] = tables.limit(l.name().charAt(0)).orElse(null);
        }
    }

    /** The G function, or null when Table 3 has no such code. */
    public GFunction g(long code) {
        return code >= 0 && code < SIZE ? g[(int) code] : null;
    }

    /** The M function, or null when Table 4 has no such code. */
    public MFunction m(long code) {
        return code >= 0 && code < SIZE ? m[(int) code] : null;
    }

    /** The Table 6 row of a word, or null when the word has none. */
    public ParameterLimit limit(Letter l) {
        return limits[l.ordinal()];
    }

    /** Table 7: the parameters function f accepts, or null when f has no row. */
    public java.util.Set<Tables.Param> allowed(int f) {
        return f >= 0 && f < SIZE ? usage[f] : null;
    }
}
