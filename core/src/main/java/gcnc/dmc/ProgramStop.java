package gcnc.dmc;

/**
 * The names a program stop (M00; M01 with the optional stop switch on) shares between the program
 * gcnc writes and the host that follows it (docs/galil.md, "Program stops"): the stop routine the
 * program calls ({@code JS #PSTOP}) and the variable it waits on ({@code gstop}, 1 while it waits;
 * the host's continue writes {@code gstop=0}).
 */
public final class ProgramStop {
    /** The label of the wait routine. */
    public static final String LABEL = "PSTOP";
    /** The variable the routine waits on. */
    public static final String FLAG = "gstop";

    private ProgramStop() {
    }
}
