package gcnc.send;

import gcnc.diag.Code;
import java.util.List;

/**
 * Why a run ends before its program does, as a diagnostic: the code (E815-E829), its arguments,
 * the G-code line it stands at (0: none), and whether anything had moved (exit status 3) or not (2).
 */
public final class RunFault extends Exception {
    private final Code code;
    private final List<String> args;
    private final int line;
    private final boolean moved;

    public RunFault(Code code, int line, boolean moved, Object... args) {
        super(code.id());
        this.code = code;
        this.line = line;
        this.moved = moved;
        this.args = java.util.Arrays.stream(args).map(String::valueOf).toList();
    }

    public Code code() {
        return code;
    }

    public List<String> args() {
        return args;
    }

    public int line() {
        return line;
    }

    /** Whether the controller had started the program (exit 3 with a resume command) or not (exit 2). */
    public boolean moved() {
        return moved;
    }
}
