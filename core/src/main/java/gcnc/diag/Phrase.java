package gcnc.diag;

import java.util.ArrayList;
import java.util.List;

/**
 * A piece of a message that is prose, not a value: "F (the lead per revolution)" in "G76 needs F
 * (the lead per revolution)". A diagnostic carries it as an argument like any other, and the
 * renderer puts it in the user's language from tables/phrases.csv (a row per constant, English and
 * Spanish), so that a Spanish message never has an English clause in it. The closed set of phrases
 * is this enum: a phrase without its row in the table is a load error, as a code without its row is.
 */
public enum Phrase {
    /** E195: a thread block without its end point on either axis. */
    THREAD_END_EITHER,
    /** E195: a thread cycle without both of its end coordinates. */
    THREAD_END_BOTH,
    /** E195: a thread without F. */
    THREAD_LEAD,
    /** E195: a G76 second block without its height ({0}: the letter). */
    THREAD_HEIGHT,
    /** E195: a G76 second block without its first depth ({0}: the letter). */
    THREAD_FIRST_DEPTH,
    /** E197: Haas M23 in force. */
    THREAD_M23,
    /** E197: a G32 straight after another pass. */
    THREAD_CONTINUED,
    /** E197: a Fanuc P/Q depth with a point. */
    THREAD_LEAST_INCREMENTS,
    /** E197: the Haas A word. */
    THREAD_ANGLE_RANGE,
    /** E197: the Haas P word. */
    THREAD_INFEED,
    /** E197: a depth no deeper than the finishing allowance ({0}). */
    THREAD_DEEPER_THAN_ALLOWANCE,
    /** E197: the Fanuc G76 P word's six digits. */
    THREAD_P_DIGITS,
    /** E197: the finishing passes mm. */
    THREAD_FINISH_PASSES,
    /** E197: a chamfer rr other than 00 ({0}). */
    THREAD_CHAMFER,
    /** E197: the angle aa. */
    THREAD_ANGLE_DIGITS,
    /** E197: the finishing allowance R. */
    THREAD_ALLOWANCE,
    /** E182: the bottom of a G75 groove. */
    PECK_BOTTOM_X,
    /** E182: the bottom of a G74 hole or face groove. */
    PECK_BOTTOM_Z,
    /** E182: no retract for a peck cycle ({0}: the cycle). */
    PECK_RETRACT,
    /** E182: the bottom of a drilled hole. */
    DRILL_BOTTOM,
    /** E182: no clearance for G83. */
    DRILL_CLEARANCE,
    /** E188: L repeats. */
    DRILL_REPEATS,
    /** E182: G83 without Q or I. */
    DRILL_PECK,
    /** E182: G83 J without I and K. */
    DRILL_PECK_J,
    /** E182: G82 without P. */
    DRILL_DWELL,
    /** E189: an allowance along the cut with a pocket, where the control moves the contour as a whole ({0} axis, {1} word). */
    POCKET_UNIFORM,
    /** E189: a pocket too narrow for the allowance on both its walls ({0}: the axis). */
    POCKET_TOO_NARROW,
    /** E500: what could not be done with a file. */
    IO_CANNOT_READ,
    IO_CANNOT_WRITE,
    IO_CANNOT_CHECK,
    IO_CANNOT_READ_OR_WRITE,
    /** E500: why, where the system's reason is one of these. */
    IO_NO_SUCH_FILE,
    IO_PERMISSION_DENIED,
    IO_IS_DIRECTORY,
    IO_NO_SPACE,
    /** E500: a folder given to check with no part program in it ({0}: the extensions). */
    IO_NO_PROGRAM;

    private static final char MARK = '\u001E';
    private static final char SEPARATOR = '\u001F';

    /** The phrase with its own arguments, as one diagnostic argument. */
    public String with(Object... args) {
        StringBuilder sb = new StringBuilder().append(MARK).append(name());
        for (Object a : args) {
            sb.append(SEPARATOR).append(a);
        }
        return sb.toString();
    }

    /** The phrase without arguments, as one diagnostic argument. */
    public String arg() {
        return with();
    }

    /**
     * Why a file could not be read or written, as an argument of E500: a phrase for the usual
     * reasons (so that it reads in the user's language), else the system's own words.
     */
    public static String reason(java.io.IOException e) {
        if (e instanceof java.nio.file.NoSuchFileException) {
            return IO_NO_SUCH_FILE.arg();
        }
        if (e instanceof java.nio.file.AccessDeniedException) {
            return IO_PERMISSION_DENIED.arg();
        }
        String text = e instanceof java.nio.file.FileSystemException f && f.getReason() != null ? f.getReason()
                : e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        if (text.equalsIgnoreCase("Is a directory")) {
            return IO_IS_DIRECTORY.arg();
        }
        if (text.toLowerCase(java.util.Locale.ROOT).contains("no space left on device")) {
            return IO_NO_SPACE.arg();
        }
        return text;
    }

    /** The phrase a diagnostic argument holds, or null when it holds a plain value. */
    public static Phrase of(String argument) {
        if (argument.isEmpty() || argument.charAt(0) != MARK) {
            return null;
        }
        int end = argument.indexOf(SEPARATOR);
        return valueOf(argument.substring(1, end < 0 ? argument.length() : end));
    }

    /** The phrase's own arguments in a diagnostic argument that holds one. */
    public static List<String> arguments(String argument) {
        List<String> out = new ArrayList<>();
        int at = argument.indexOf(SEPARATOR);
        while (at >= 0) {
            int next = argument.indexOf(SEPARATOR, at + 1);
            out.add(argument.substring(at + 1, next < 0 ? argument.length() : next));
            at = next;
        }
        return out;
    }
}
