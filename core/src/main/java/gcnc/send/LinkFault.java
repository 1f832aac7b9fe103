package gcnc.send;

import java.io.IOException;

/**
 * The link failed the protocol: it closed, the controller did not answer in time, or it answered
 * something that is not Galil's protocol. The caller stops the machine (if it still can) and
 * reports which block was last completed and which was executing.
 */
public final class LinkFault extends IOException {
    /** How the link failed. */
    public enum Kind { DROPPED, TIMEOUT, GARBAGE }

    private final Kind kind;
    private final String command;
    private final String detail;

    public LinkFault(Kind kind, String command, String detail) {
        super(kind + " after '" + command + "': " + detail);
        this.kind = kind;
        this.command = command;
        this.detail = detail;
    }

    public Kind kind() {
        return kind;
    }

    /** The command whose reply was awaited, as sent (without its CR). */
    public String command() {
        return command;
    }

    /** What came instead of a reply (printable), or why nothing came. */
    public String detail() {
        return detail;
    }
}
