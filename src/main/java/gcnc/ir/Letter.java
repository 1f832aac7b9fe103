package gcnc.ir;

/** The address letters of the thesis's language (§3.3). Anything else is error 4. */
public enum Letter {
    N, O, G, M, X, Z, U, W, I, K, R, P, S, F, T;

    private static final Letter[] BY_CHAR = new Letter[128];

    static {
        for (Letter l : values()) {
            BY_CHAR[l.name().charAt(0)] = l;
            BY_CHAR[Character.toLowerCase(l.name().charAt(0))] = l;
        }
    }

    /** The letter for a character in either case, or null when the language has no such address. */
    public static Letter of(char c) {
        return c < 128 ? BY_CHAR[c] : null;
    }
}
