package gcnc.machine;

import gcnc.diag.Code;
import java.util.Map;
import java.util.OptionalInt;

/**
 * One Galil controller model and what it takes: a row of tables/galil_models.csv, picked by a
 * machine profile's {@code galil.model} ({@link GalilModels}). The numbers are the command
 * reference's argument ranges and the model's program memory (docs/galil.md, "The controller's
 * limits", names the source of each); {@link ControllerLimits} checks a value against them.
 *
 * @param name           the model as a profile names it, e.g. DMC-4040
 * @param family         the series it belongs to, e.g. DMC-40x0
 * @param axes           motion channels (A, B, C ... or X, Y, Z, W)
 * @param digitalOutputs general outputs SB and CB can set (1 to this)
 * @param analogOutputs  general analog outputs beside the axes' motor command outputs, -1 when not verified
 * @param sampleMicros   the servo sample time TM at power-up, microseconds (speeds and times are at TM 1000)
 * @param limits         each limit's allowed values, for firmware before 1.2a
 * @param firmware12a    the limits firmware 1.2a and later raises (program lines, array elements); empty
 *                       where the reference's 1.2a figures are not known to apply to the model
 * @param newFirmware    whether this copy holds the 1.2a figures ({@link #withFirmware12a})
 * @param hostLink       how a host reaches it: a serial and an Ethernet port, or only a computer's bus
 * @param serialEcho     whether its serial port echoes every character at power-up (COMALL EO: "defaulted
 *                       to EO1"; false where a model's manual says echo is off until EO 1)
 * @param deviations     the probe rows ({@link ProbeRow} ids) the profile states its unit contradicts
 *                       ({@code galil.deviations}): gcnc run accepts a probe report that contradicts them
 * @param row            the model's line in tables/galil_models.csv
 */
public record GalilModel(String name, String family, int axes, int digitalOutputs, int analogOutputs,
                         int sampleMicros, Map<Limit, Range> limits, Map<Limit, Range> firmware12a,
                         boolean newFirmware, HostLink hostLink, boolean serialEcho, java.util.List<String> deviations,
                         int row) {
    /**
     * How a host talks to the controller (tables/galil_models.csv, column host_link). gcnc run speaks
     * serial and Ethernet; a bus card (ISA DMC-1700, PCI DMC-18x6: DMC-1700/1800 User Manual ch.4,
     * "Hardware Level Communications for ISA and PCI") needs Galil's bus driver.
     */
    public enum HostLink {
        SERIAL_ETHERNET, BUS;

        /** The constant's name in lower case with hyphens, as the table's host_link column writes it. */
        public String spelling() {
            return name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
        }
    }

    /** Whether gcnc run (serial or TCP) cannot reach the model: a bus card. */
    public boolean busOnly() {
        return hostLink == HostLink.BUS;
    }

    public GalilModel {
        limits = Map.copyOf(limits);
        firmware12a = Map.copyOf(firmware12a);
        deviations = java.util.List.copyOf(deviations);
    }

    /** The same model with the deviations a profile states ({@code galil.deviations}). */
    public GalilModel withDeviations(java.util.List<String> ids) {
        return new GalilModel(name, family, axes, digitalOutputs, analogOutputs, sampleMicros, limits, firmware12a,
                newFirmware, hostLink, serialEcho, ids, row);
    }

    /**
     * What the controller takes for one kind of value, inclusive from {@code min} to {@code max}
     * ({@code max} itself excluded when the limit is {@link Limit#below}), in steps of {@code step}
     * from zero (a value between steps is rounded by the controller, not refused).
     */
    public record Range(long min, long max, long step) {
        public boolean holds(double v, boolean below) {
            return v >= min && (below ? v < max : v <= max);
        }
    }

    /**
     * The closed set of limits a model has: the command or budget each bounds, the columns of
     * tables/galil_models.csv that give its minimum, maximum and step (null: 0 or 1), and the error
     * a value beyond it is. The reference entry is the COMALL command whose argument table says it.
     */
    public enum Limit {
        /** VS, counts/s at TM 1000. */
        VECTOR_SPEED("VS", "speed_min", "speed_max", "speed_step", false, Code.E220_VECTOR_SPEED_RANGE),
        /** The segment speeds {@code <o >p} of VP and CR, counts/s at TM 1000. */
        SEGMENT_SPEED("VP <o >p", "speed_min", "speed_max", "speed_step", false, Code.E221_SEGMENT_SPEED_RANGE),
        /** VA and VD, counts/s^2 at TM 1000. */
        ACCELERATION("VA VD", "accel_min", "accel_max", "accel_step", false, Code.E222_ACCELERATION_RANGE),
        /** The length of one VP segment, counts. */
        SEGMENT_LENGTH("VP", null, "segment_max", null, false, Code.E223_SEGMENT_TOO_LONG),
        /** The radius of a CR arc, counts. */
        ARC_RADIUS("CR", "radius_min", "radius_max", null, false, Code.E224_ARC_RADIUS_RANGE),
        /** A CR arc's radius times the degrees it turns: less than the maximum. */
        ARC_LENGTH("CR", null, "arc_max", null, true, Code.E225_ARC_TOO_LONG),
        /** WT, milliseconds at TM 1000. */
        DWELL("WT", "dwell_min", "dwell_max", "dwell_step", false, Code.E226_DWELL_RANGE),
        /** Characters on one program line. */
        LINE_LENGTH("DL", null, "line_chars", null, false, Code.E227_LINE_TOO_LONG),
        /** Lines of one downloaded program. */
        PROGRAM_LINES("DL XQ", null, "program_lines", null, false, Code.E228_TOO_MANY_LINES),
        /** Labels in one downloaded program. */
        LABELS("#", null, "labels", null, false, Code.E229_TOO_MANY_LABELS),
        /** Characters of one label's name (after the #). */
        LABEL_LENGTH("#", null, "label_chars", null, false, Code.E230_LABEL_TOO_LONG),
        /** Variables a program may create. */
        VARIABLES("_UL", null, "variables", null, false, Code.E231_TOO_MANY_VARIABLES),
        /** Array elements, all arrays together. */
        ARRAY_ELEMENTS("DM", null, "array_elements", null, false, Code.E232_TOO_MANY_ARRAY_ELEMENTS),
        /** The path length of one sequence (from its BGS), counts: less than the maximum. */
        SEQUENCE_LENGTH("LI BGS", null, "sequence_max", null, true, Code.E233_SEQUENCE_TOO_LONG),
        /** Segments given before BGS (the sequence buffer). */
        BUFFER_SEGMENTS("VM BGS", null, "buffer_segments", null, false, Code.E234_TOO_MANY_SEGMENTS);

        private final String command;
        private final String minColumn;
        private final String maxColumn;
        private final String stepColumn;
        private final boolean below;
        private final Code code;

        Limit(String command, String minColumn, String maxColumn, String stepColumn, boolean below, Code code) {
            this.command = command;
            this.minColumn = minColumn;
            this.maxColumn = maxColumn;
            this.stepColumn = stepColumn;
            this.below = below;
            this.code = code;
        }

        /** The Galil command (or operand) the limit is the reference's argument range of. */
        public String command() {
            return command;
        }

        String minColumn() {
            return minColumn;
        }

        String maxColumn() {
            return maxColumn;
        }

        String stepColumn() {
            return stepColumn;
        }

        /** The maximum is a bound the value must stay below (the reference says "less than"). */
        public boolean below() {
            return below;
        }

        /** The error a value beyond the limit is. */
        public Code code() {
            return code;
        }
    }

    /** What the model takes for {@code limit}, with the 1.2a figures when {@link #newFirmware}. */
    public Range range(Limit limit) {
        if (newFirmware && firmware12a.containsKey(limit)) {
            return firmware12a.get(limit);
        }
        return limits.get(limit);
    }

    /** General analog outputs, empty where the count was not verified. */
    public OptionalInt analogOutputCount() {
        return analogOutputs < 0 ? OptionalInt.empty() : OptionalInt.of(analogOutputs);
    }

    /** Whether firmware 1.2a and later changes a limit of this model (more program lines, more array space). */
    public boolean hasFirmware12a() {
        return !firmware12a.isEmpty();
    }

    /** The same model at firmware before 1.2a (a controller that reported an older revision). */
    public GalilModel withOlderFirmware() {
        return new GalilModel(name, family, axes, digitalOutputs, analogOutputs, sampleMicros, limits, firmware12a,
                false, hostLink, serialEcho, deviations, row);
    }

    /** The same model running firmware 1.2a or later: its larger program memory where the reference gives one. */
    public GalilModel withFirmware12a() {
        return new GalilModel(name, family, axes, digitalOutputs, analogOutputs, sampleMicros, limits, firmware12a,
                true, hostLink, serialEcho, deviations, row);
    }

    /** A channel letter's number from 0 (X, Y, Z, W are A, B, C, D); whether the model has it. */
    public boolean hasChannel(char letter) {
        int xyzw = "XYZW".indexOf(letter);
        int n = xyzw >= 0 ? xyzw : letter - 'A';
        return n >= 0 && n < axes;
    }

    /** The channel letters the model has, e.g. "A-D (X, Y, Z, W)" for four axes. */
    public String channels() {
        String last = String.valueOf((char) ('A' + axes - 1));
        String abc = axes == 1 ? "A" : "A-" + last;
        return axes <= 4 ? abc + " (" + String.join(", ", java.util.List.of("X", "Y", "Z", "W").subList(0, axes)) + ")"
                : abc + " (X, Y, Z, W = A-D)";
    }
}
