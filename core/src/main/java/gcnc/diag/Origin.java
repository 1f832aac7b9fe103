package gcnc.diag;

import java.util.List;

/**
 * Where a finding's block comes from when it is not simply the program file as written: the file
 * it is in ({@code null}: the program's own file, whose path the front end knows) and the calls
 * that led to it, innermost first (empty: the main program). A block of a subprogram is checked
 * once per call; its findings name the subprogram's line, and each call is a note (E136).
 */
public record Origin(String file, List<Call> calls) {
    /** The program file as written, no call. */
    public static final Origin PROGRAM = new Origin(null, List.of());
    /**
     * This very instance (compared by identity) marks a finding made without saying where it
     * belongs: {@link Diagnostics#report} places it where the blocks now checked come from.
     * Rendered, it is the program file.
     */
    public static final Origin UNPLACED = new Origin(null, List.of());

    /**
     * One call: what is called ("O1000", or "N100" for a Haas M97), the line and words of the call in its
     * caller, and the file the caller is in ({@code null}: the program's own).
     */
    public record Call(String program, int line, String words, String file) {
    }

    public Origin {
        calls = List.copyOf(calls);
    }

    /** Blocks of another file, no call (the parser's findings in a called program's own file). */
    public static Origin file(String file) {
        return new Origin(file, List.of());
    }

    /** The same file without the calls: where the notes about the calls are placed. */
    public Origin withoutCalls() {
        return calls.isEmpty() ? this : new Origin(file, List.of());
    }
}
