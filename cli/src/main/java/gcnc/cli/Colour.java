package gcnc.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import picocli.CommandLine.Help.Ansi.Style;

/**
 * Colour in the GNU report, as GCC colours it: the place bold, "error" bold red, "warning" bold
 * magenta, "note" bold cyan, the caret green; the escape codes are picocli's ({@link Style}). On
 * only where a person reads it: {@code --color always}, or {@code auto} (the default) on a
 * terminal without {@code NO_COLOR} (no-color.org: set and not empty, it turns colour off) and
 * with a {@code TERM} other than {@code dumb}. Off, the report is byte for byte what it is without
 * this class: a pipe, a file, CI logs and the tests see no escape code.
 */
final class Colour {
    /** {@code --color}. */
    enum When { AUTO, ALWAYS, NEVER }

    /** No colour at all: every method gives back its text unchanged. */
    static final Colour OFF = new Colour(false);

    private final boolean on;

    private Colour(boolean on) {
        this.on = on;
    }

    /** The colour for this run, from {@code --color}, the environment and whether standard error is a terminal. */
    static Colour of(When when, Map<String, String> env, boolean terminal) {
        return new Colour(enabled(when, env, terminal));
    }

    /** The decision alone (ColourTest): always, never, or auto on a terminal without NO_COLOR or TERM=dumb. */
    static boolean enabled(When when, Map<String, String> env, boolean terminal) {
        if (when != When.AUTO) {
            return when == When.ALWAYS;
        }
        String noColor = env.get("NO_COLOR");
        return terminal && (noColor == null || noColor.isEmpty()) && !"dumb".equals(env.get("TERM"));
    }

    /**
     * Whether standard error goes to a terminal: Java's console says standard input and output
     * are one; on Linux /proc says where standard error goes (a tty or pts device), so that
     * {@code gcnc check part.nc 2> log} writes no escape codes into the log.
     */
    static boolean stderrIsTerminal() {
        if (System.console() == null) {
            return false;
        }
        try {
            String target = Files.readSymbolicLink(Path.of("/proc/self/fd/2")).toString();
            return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty");
        } catch (java.io.IOException | UnsupportedOperationException | SecurityException e) {
            return true; // no /proc (not Linux): the console is all there is to go by
        }
    }

    boolean on() {
        return on;
    }

    /** The place of a finding, {@code part.nc:12:7:}. */
    String place(String text) {
        return paint(text, Style.bold);
    }

    /** A severity label, in GCC's colour for it. */
    String severity(gcnc.diag.Severity s, String label) {
        return switch (s) {
            case ERROR -> paint(label, Style.bold, Style.fg_red);
            case WARNING -> paint(label, Style.bold, Style.fg_magenta);
            case NOTE -> paint(label, Style.bold, Style.fg_cyan);
        };
    }

    /** The caret line under a program's line. */
    String caret(String text) {
        return paint(text, Style.bold, Style.fg_green);
    }

    /** The command a hint names. */
    String command(String text) {
        return paint(text, Style.bold);
    }

    private String paint(String text, Style... styles) {
        // reset, not each style's own off: picocli's bold off is SGR 21, which some terminals draw as a double underline
        return on && !text.isEmpty() ? Style.on(styles) + text + Style.reset.on() : text;
    }
}
