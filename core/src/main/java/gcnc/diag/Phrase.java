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
    /** E197: a start angle Q (G92, Haas G76). */
    THREAD_START_ANGLE,
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
    /** E188: C or H on a Fanuc drilling cycle (live tooling). */
    DRILL_C_AXIS,
    /** E188: W on a Fanuc drilling cycle (the bottom from the R point). */
    DRILL_BOTTOM_W,
    /** E188: Q on a tapping cycle (peck tapping). */
    TAP_PECK,
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
    /** E622-E624: a block that runs the modal cycle {0} again under G41/G42. */
    CYCLE_AGAIN,
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
    IO_NO_PROGRAM,
    /*
     * E400: a fault in a table, a control or a machine profile (gcnc.tables, gcnc.machine), each
     * sentence a phrase so that `gcnc --lang es machines validate` reads Spanish throughout. The
     * values, keys and file names in them are arguments, written as the user wrote them.
     */
    CSV_MISSING_COLUMN,
    CSV_MISSING_VALUE,
    CSV_NOT_WHOLE,
    CSV_FIELD_COUNT,
    CSV_EMPTY,
    NOT_A_NUMBER,
    NOT_UTF8,
    TABLE_NOT_IN_JAR,
    TABLE_FILE_NOT_FOUND,
    SEVERITY,
    WORD_ONE_LETTER,
    WORD_TWICE,
    LISTED_TWICE_FIRST,
    LISTED_TWICE,
    LOWER_ABOVE_UPPER,
    ONE_OF_TWO,
    OFFSETS_IN_ORDER,
    NO_ROW_FOR_CODE,
    NO_SUCH_PHRASE,
    NO_ROW_FOR_PHRASE,
    NO_SUCH_CODE,
    TEMPLATE_BROKEN,
    TEMPLATE_UNCLOSED,
    TEMPLATE_PLACEHOLDER,
    EXPECTED_KEY_VALUE,
    MISSING_KEY_BEFORE_EQUALS,
    KEY_GIVEN_TWICE,
    MISSING_REQUIRED_KEY,
    GREATER_THAN_ZERO,
    TWO_NUMBERS,
    ONE_OF,
    PROFILE_NOT_FOUND,
    SAME_CHANNEL,
    ENCODER_AXIS_NEEDS_ENCODER,
    ENCODER_COUNTS,
    ENCODER_ON_TOOL_AXIS,
    CONTROL_FAULT,
    SIGN,
    TRAVEL_ORDER,
    TRAVEL_REGISTER,
    CHANNEL_LETTER,
    SPINDLE_ON_TOOL_AXIS,
    OUTSIDE_TRAVEL,
    REGISTER_SPEED,
    REGISTER_ACCELERATION,
    REGISTER_DECELERATION,
    TOOL_OFFSET_FROM_ONE,
    TOOLS_OFFSETS_RANGE,
    TOOLS_COUNT_RANGE,
    NOSE_FROM_ONE,
    NOSE_RADIUS,
    TIP_DIRECTION,
    THREAD_CHAMFER_LEADS,
    THREAD_CHAMFER_ANGLE,
    OUTPUT_DIRECTIVES,
    NUMBER_AGAIN,
    UNKNOWN_KEY_TYPO,
    UNKNOWN_KEY_WORK,
    UNKNOWN_KEY_TOOL,
    UNKNOWN_KEY_NOSE,
    UNKNOWN_KEY_WEAR,
    /** wear.0: wear offsets are numbered from 1 ({0}: the key). */
    WEAR_FROM_ONE,
    UNKNOWN_KEY_M,
    UNKNOWN_KEY_SIM_TOOL,
    UNKNOWN_KEY_DOCS,
    UNKNOWN_CONTROL_KEY,
    NO_CONTROL,
    /** A control name that is not shipped but near one: {0} the name, {1} the nearest, {2} the shipped ones. */
    NO_CONTROL_TYPO,
    /** A machine name that is not a shipped profile: {0} the name, {1} the shipped ones. */
    NO_MACHINE,
    /** A machine name near a shipped profile's: {0} the name, {1} the nearest, {2} the shipped ones. */
    NO_MACHINE_TYPO,
    LETTERS,
    POWER_UP,
    LENGTH_MM,
    CALL_DEPTH,
    /** A control's stop.off names an M code that is neither a spindle stop nor an output of its M table ({0}). */
    STOP_OFF,
    UNKNOWN_FUNCTION,
    MOMENT,
    OUTPUT_YES_NO,
    CODE_RANGE,
    GROUP_RANGE,
    WORDS,
    CHUCK_FACE,
    TAILSTOCK_CENTRE,
    STOCK_NEEDS_CHUCK,
    STICKOUT,
    KEYS_TOGETHER,
    TOOL_AGAIN,
    TOOL_FROM_LIBRARY,
    POINT_LIST,
    CONVEX,
    WORK_AT_FACE,
    STATION_FORM,
    STATION_FROM_ONE,
    STATION_ANGLE,
    STATION_TWICE,
    NOSE_TWICE,
    UNKNOWN_KEY_STATION,
    TOOL_ASSUMED,
    TOOLS_FILE_MISSING,
    TOOLS_FILE_KEYS,
    /** A simulator finding's place when the program's coordinates are not known (a DMC replayed by itself): {0} the DMC line. */
    DMC_LINE,
    /** E420: the nearest known Galil model ({0}). */
    DID_YOU_MEAN,
    /** galil_models.csv: a model name that is not DMC- and four or five digits ({0}). */
    GALIL_MODEL_NAME,
    /** galil_models.csv: a model listed twice ({0}, first on line {1}). */
    GALIL_MODEL_TWICE,
    /** galil_models.csv: a whole number outside what the column can hold ({0} column, {1} value, {2}..{3}). */
    GALIL_MODEL_RANGE,
    /** galil_models.csv: a cell outside its column's words ({0} column, {1} value, {2} the words it takes). */
    GALIL_MODEL_CHOICE,
    /** galil_models.csv: a firmware-1.2a figure smaller than the older one ({0} column, {1} the older column). */
    GALIL_FIRMWARE_SMALLER,
    /** The last line of a GCC-style report (as rustc's): where to read more about an error ({0}: its code). */
    EXPLAIN_HINT_ERROR,
    /** The same for a run whose findings are warnings only ({0}: the first warning's code). */
    EXPLAIN_HINT_WARNING,
    /** A waived finding's GCC-style text ({0}: the waiver's reason, {1}: the finding's message). */
    WAIVED;

    private static final char MARK = '\u001E';
    private static final char SEPARATOR = '\u001F';

    /**
     * A phrase inside another phrase's argument (E400's "control 'x': place: why"), its marks
     * swapped for these so that it stays one argument of the outer phrase.
     */
    private static final char INNER_MARK = '\u001C';
    private static final char INNER_SEPARATOR = '\u001D';

    /**
     * The phrase with its own arguments, as one diagnostic argument. An argument that is itself a
     * phrase is kept as one (one level deep), and rendered in the same language.
     */
    public String with(Object... args) {
        StringBuilder sb = new StringBuilder().append(MARK).append(name());
        for (Object a : args) {
            String text = String.valueOf(a);
            if (!text.isEmpty() && text.charAt(0) == MARK) {
                text = text.replace(MARK, INNER_MARK).replace(SEPARATOR, INNER_SEPARATOR);
            }
            sb.append(SEPARATOR).append(text);
        }
        return sb.toString();
    }

    /** A phrase's argument as a diagnostic argument: a phrase nested by {@link #with} is one again. */
    public static String unnested(String argument) {
        if (argument.isEmpty() || argument.charAt(0) != INNER_MARK) {
            return argument;
        }
        return argument.replace(INNER_MARK, MARK).replace(INNER_SEPARATOR, SEPARATOR);
    }

    /** Whether a diagnostic argument is a phrase (known to this gcnc or not). */
    public static boolean marked(String argument) {
        return !argument.isEmpty() && argument.charAt(0) == MARK;
    }

    /**
     * A phrase argument without its table, for the last resort: the constant's name and its
     * arguments, so that a message that cannot be put into words still says what it is.
     */
    public static String plain(String argument) {
        if (!marked(argument)) {
            return argument;
        }
        StringBuilder sb = new StringBuilder();
        int end = argument.indexOf(SEPARATOR);
        sb.append(argument, 1, end < 0 ? argument.length() : end);
        for (String a : arguments(argument)) {
            sb.append(' ').append(plain(unnested(a)));
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

    /**
     * The phrase a diagnostic argument holds, or null when it holds a plain value or a phrase this
     * gcnc does not have ({@link #marked} tells the two apart).
     */
    public static Phrase of(String argument) {
        if (!marked(argument)) {
            return null;
        }
        int end = argument.indexOf(SEPARATOR);
        try {
            return valueOf(argument.substring(1, end < 0 ? argument.length() : end));
        } catch (IllegalArgumentException e) {
            return null;
        }
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
