package gcnc.dmc;

import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The message each of the program's fault routines sends before its common stop ({@code #FAULT}:
 * ST, the spindle off, EN; docs/galil.md, "Error handlers"): {@code MG "LIMIT SWITCH AT G-CODE
 * LINE",gline}, which the controller prints as {@code LIMIT SWITCH AT G-CODE LINE 14.0000}. The
 * program that writes it and the host that follows it share the words here, so that the host reads
 * a fault from them (a sequence the host streams must not go on after the controller stopped it).
 * A program stop ({@link ProgramStop}) says the same words after {@link #PROGRAM_STOP}: it is no fault.
 */
public final class FaultMessage {
    /** What follows the fault's name, before the G-code line the program had reached. */
    public static final String AT = " AT G-CODE LINE";
    /** The words of a program stop's message (M00, M01 with the switch on). */
    public static final String PROGRAM_STOP = "PROGRAM STOP";

    private static final Pattern LINE = Pattern.compile("\\s*(.+?)" + AT + "\\s*(-?[0-9]+)(?:\\.[0-9]*)?\\s*");

    /** A fault the controller reported: its words ("LIMIT SWITCH") and the G-code line it names. */
    public record Fault(String what, int line) {
        @Override
        public String toString() {
            return what + AT + " " + line;
        }
    }

    private FaultMessage() {
    }

    /** The fault an unsolicited line reports, when it is a fault routine's message; empty for anything else. */
    public static Optional<Fault> read(String line) {
        Matcher m = LINE.matcher(line);
        if (!m.matches() || m.group(1).equals(PROGRAM_STOP)) {
            return Optional.empty();
        }
        try {
            return Optional.of(new Fault(m.group(1), Integer.parseInt(m.group(2))));
        } catch (NumberFormatException e) {
            return Optional.empty(); // a line number past an int is no line gcnc wrote
        }
    }
}
