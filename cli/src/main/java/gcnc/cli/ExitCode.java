package gcnc.cli;

/** gcnc's exit statuses, as documented in the README. */
final class ExitCode {
    static final int CLEAN = 0;
    static final int PROGRAM_ERRORS = 1;
    static final int USAGE = 2;

    private ExitCode() {
    }
}
