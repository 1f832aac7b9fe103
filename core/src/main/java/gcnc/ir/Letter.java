package gcnc.ir;

/**
 * The address letters of a word: every letter A-Z. The first fifteen are the thesis's language
 * (§3.3), in its order; the others follow in alphabetical order. The parser reads every letter;
 * which ones a control reads is the checker's business (error 4 for the others).
 */
public enum Letter {
    N, O, G, M, X, Z, U, W, I, K, R, P, S, F, T,
    A, B, C, D, E, H, J, L, Q, V, Y;

    private static final Letter[] BY_CHAR = new Letter[128];

    static {
        for (Letter l : values()) {
            BY_CHAR[l.name().charAt(0)] = l;
            BY_CHAR[Character.toLowerCase(l.name().charAt(0))] = l;
        }
    }

    /** The letter for an ASCII letter in either case, or null for any other character. */
    public static Letter of(char c) {
        return c < 128 ? BY_CHAR[c] : null;
    }
}
