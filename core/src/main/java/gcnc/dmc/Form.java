package gcnc.dmc;

/**
 * The two shapes a compiled program takes for the controller (docs/galil.md, "Two forms").
 * {@link #PROGRAM}: one program downloaded whole ({@code DL}) and run by the controller; it must fit
 * the model's program memory. {@link #STREAM}: a small resident program (the set-up, the error
 * handlers, the wait routines and the few blocks that must run inside the controller, such as
 * threads) downloaded once, and a segment stream of commands the host feeds the controller while it
 * runs: any length.
 */
public enum Form {
    PROGRAM,
    STREAM;

    /** Its name on the command line and in the outputs ({@code --form program}): the constant's, in lower case. */
    public String key() {
        return name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
    }

    /** The form named {@code key}, or null. */
    public static Form of(String key) {
        for (Form f : values()) {
            if (f.key().equals(key)) {
                return f;
            }
        }
        return null;
    }
}
