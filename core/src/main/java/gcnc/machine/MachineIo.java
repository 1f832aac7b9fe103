package gcnc.machine;

import gcnc.diag.Code;
import gcnc.tables.TableException;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The machine around the motion, from the profile (docs/profiles.md, "Spindle, turret and
 * homing"): how the spindle drive gets its speed reference, how the program waits for the spindle
 * to reach speed, the turret's outputs and its answer, and how the program makes sure the machine
 * stands at home before it moves. Read when the profile is loaded (a fault at the value's line,
 * E430-E434) and again, from the same checked text, by the backend and the simulator.
 *
 * @param drive    the spindle's speed reference: the OF of a servoed channel, or an analog output
 * @param atSpeed  what the program waits for after M03/M04 or a speed change, before it feeds
 * @param turret   the turret's outputs and in-position input; empty: only {@code TOOL=n} is written
 * @param homing   what proves the machine is at home before the first move
 * @param cycleStart the input of the machine's cycle start button ({@code stop.cycle_start = IN n}),
 *                 which ends a program stop as the host's continue does; empty: the host's only
 */
public record MachineIo(SpindleDrive drive, AtSpeed atSpeed, Optional<Turret> turret, Homing homing,
                        java.util.OptionalInt cycleStart) {
    /** Where the spindle drive's speed reference comes from. */
    public sealed interface SpindleDrive {
        /**
         * {@code OF} on a channel servoed with zero gains (KP, KI, KD 0; ER -1): with the gains at
         * zero the motor command output equals OF (Galil's OF page), so the channel is a ±10 V output.
         */
        record Offset(char channel) implements SpindleDrive {
        }

        /**
         * {@code AO n,v}: the analog output with I/O number n of a Modbus device (an I/O module, a
         * RIO) on the controller's Modbus handle; the controllers themselves have no general analog
         * outputs (AO "sets the analog output voltage of Modbus Devices", DMC-40x0 Command
         * Reference p.28; tables/galil_models.csv). The shop sets up the handle outside the program.
         */
        record Analog(int output) implements SpindleDrive {
        }
    }

    /** What "at speed" is. */
    public sealed interface AtSpeed {
        <R> R accept(Visitor<R> v);

        /** An input from the spindle drive, on at speed; waited for with a timeout. */
        record Input(int input, double timeoutSeconds) implements AtSpeed {
            public <R> R accept(Visitor<R> v) {
                return v.input(this);
            }
        }

        /** A dwell long enough for the spindle to run up. */
        record Dwell(double seconds) implements AtSpeed {
            public <R> R accept(Visitor<R> v) {
                return v.dwell(this);
            }
        }

        /** No wait (the drive is fast, or the operator waits). */
        record None() implements AtSpeed {
            public <R> R accept(Visitor<R> v) {
                return v.none(this);
            }
        }

        /** One method per kind of wait: a new one does not compile until each visitor handles it. */
        interface Visitor<R> {
            R input(Input a);

            R dwell(Dwell a);

            R none(None a);
        }
    }

    /**
     * A turret indexed by outputs: the station number in binary on {@code stationOutputs} (least
     * significant bit first), then {@code strobe} on; the turret answers on {@code inPosition} when
     * it is locked at that station; {@code strobe} goes off again. No answer within the timeout
     * stops the program.
     */
    public record Turret(List<Integer> stationOutputs, int strobe, int inPosition, double timeoutSeconds) {
        public Turret {
            stationOutputs = List.copyOf(stationOutputs);
        }
    }

    /** What proves the machine is at home when the program starts. */
    public sealed interface Homing {
        <R> R accept(Visitor<R> v);

        /** Both axes stand at the profile's {@code home} within the tolerance ({@code _TP}, after homing and DP). */
        record Position(double toleranceMm) implements Homing {
            public <R> R accept(Visitor<R> v) {
                return v.position(this);
            }
        }

        /** An input that is on once the machine has been homed (a PLC's reference-done signal). */
        record Input(int input) implements Homing {
            public <R> R accept(Visitor<R> v) {
                return v.input(this);
            }
        }

        /** No check (the operator's responsibility). */
        record None() implements Homing {
            public <R> R accept(Visitor<R> v) {
                return v.none(this);
            }
        }

        /** One method per proof of home: a new one does not compile until each visitor handles it. */
        interface Visitor<R> {
            R position(Position h);

            R input(Input h);

            R none(None h);
        }
    }

    /** Defaults when the profile says nothing: OF on spindle.axis, a 2 s dwell, no turret outputs, a position check within 0.01 mm. */
    static final double DEFAULT_DWELL = 2;
    static final double DEFAULT_TIMEOUT = 10;
    static final double DEFAULT_TOLERANCE_MM = 0.01;

    private static final Pattern OFFSET = Pattern.compile("OF(?:\\s*([A-HXYZW]))?", Pattern.CASE_INSENSITIVE);
    private static final Pattern ANALOG = Pattern.compile("AO\\s*([0-9]{1,5})", Pattern.CASE_INSENSITIVE);
    /**
     * The I/O numbers AO takes: a Modbus device's analog output, 1,000 to 8,999 ("n0 = (HandleNum*1000) +
     * ((Module-1)*4) + (Bitnum-1)", command reference AO; its only range for n0): a number below 1,000
     * is refused by the controller, so the profile is refused here (E437).
     */
    static final int MIN_ANALOG = 1000;
    static final int MAX_ANALOG = 8999;
    private static final Pattern INPUT = Pattern.compile("IN\\s*([0-9]{1,5})", Pattern.CASE_INSENSITIVE);
    /**
     * The digital inputs {@code @IN[n]} reads (command reference @IN): the general inputs 1 to 16 ("Inputs
     * 9-16 only valid for 5-8 axis controller", the split @OUT makes for outputs, so the model's
     * digital_outputs column bounds them), the auxiliary encoder inputs 81 to 96 ("Used when repurposing
     * aux encoder inputs as digital inputs") and a Modbus device's bits, 1,000 to 8,999.
     */
    static final int MIN_AUX_INPUT = 81;
    static final int MAX_AUX_INPUT = 96;
    private static final Pattern SECONDS = Pattern.compile("([0-9]{1,3}(?:\\.[0-9]{1,3})?)\\s*s", Pattern.CASE_INSENSITIVE);
    /** Galil's digital inputs and outputs are numbered from 1; 999 is far above any model's extended I/O. */
    private static final int MAX_BIT = 999;

    /** The profile's machine I/O (checked when it was loaded); the defaults for a profile built without a file. */
    public static MachineIo of(MachineProfile p) {
        try {
            return p.file() == null ? defaults(p.spindleAxis())
                    : read(p.file(), p.spindleAxis(), p.tools(), p.galilModel());
        } catch (TableException e) {
            throw new IllegalStateException("the machine I/O keys were checked when the profile was loaded", e);
        }
    }

    static MachineIo defaults(char spindleAxis) {
        return new MachineIo(new SpindleDrive.Offset(spindleAxis), new AtSpeed.Dwell(DEFAULT_DWELL), Optional.empty(),
                new Homing.Position(DEFAULT_TOLERANCE_MM), java.util.OptionalInt.empty());
    }

    /** The keys of {@code f}, checked against the turret's station count and the model's digital outputs (E424). */
    static MachineIo read(ProfileFile f, char spindleAxis, int tools, GalilModel model) throws TableException {
        return new MachineIo(drive(f, spindleAxis), atSpeed(f, model), turret(f, tools, model), homing(f, model), cycleStart(f, model));
    }

    /** {@code stop.cycle_start = IN n}: the cycle start button's input (on = pressed, read {@code @IN[n]=1}). */
    private static java.util.OptionalInt cycleStart(ProfileFile f, GalilModel model) throws TableException {
        Optional<ProfileFile.Entry> e = f.entry("stop.cycle_start");
        if (e.isEmpty()) {
            return java.util.OptionalInt.empty();
        }
        Matcher m = INPUT.matcher(e.get().value().strip());
        if (m.matches()) {
            return java.util.OptionalInt.of(input(f, e.get(), m.group(1), model)); // an input the model reads, else E436
        }
        throw f.fault(e.get(), Code.E850_CYCLE_START_INPUT, e.get().value().strip());
    }

    private static SpindleDrive drive(ProfileFile f, char spindleAxis) throws TableException {
        Optional<ProfileFile.Entry> e = f.entry("spindle.output");
        if (e.isEmpty()) {
            return new SpindleDrive.Offset(spindleAxis);
        }
        String v = e.get().value().strip();
        Matcher m = OFFSET.matcher(v);
        if (m.matches() && (m.group(1) == null
                || Plane.channel(Character.toUpperCase(m.group(1).charAt(0))) == Plane.channel(spindleAxis))) {
            return new SpindleDrive.Offset(spindleAxis);
        }
        m = ANALOG.matcher(v);
        if (m.matches()) {
            int n = Integer.parseInt(m.group(1));
            if (n < MIN_ANALOG || n > MAX_ANALOG) {
                throw f.fault(e.get(), Code.E437_ANALOG_OUTPUT_RANGE, String.valueOf(n), String.valueOf(spindleAxis));
            }
            return new SpindleDrive.Analog(n);
        }
        throw f.fault(e.get(), Code.E430_SPINDLE_OUTPUT, v, String.valueOf(spindleAxis));
    }

    private static AtSpeed atSpeed(ProfileFile f, GalilModel model) throws TableException {
        Optional<ProfileFile.Entry> e = f.entry("spindle.at_speed");
        double timeout = f.entry("spindle.at_speed_timeout").isPresent()
                ? f.within("spindle.at_speed_timeout", 0.1, 600) : DEFAULT_TIMEOUT;
        if (e.isEmpty()) {
            return new AtSpeed.Dwell(DEFAULT_DWELL);
        }
        String v = e.get().value().strip();
        Matcher m = INPUT.matcher(v);
        if (m.matches()) {
            return new AtSpeed.Input(input(f, e.get(), m.group(1), model), timeout);
        }
        m = SECONDS.matcher(v);
        if (m.matches() && Double.parseDouble(m.group(1)) >= 0.002 && Double.parseDouble(m.group(1)) <= 600) {
            return new AtSpeed.Dwell(Double.parseDouble(m.group(1)));
        }
        if (v.equalsIgnoreCase("none")) {
            return new AtSpeed.None();
        }
        throw f.fault(e.get(), Code.E431_SPINDLE_AT_SPEED, v);
    }

    private static final List<String> TURRET_KEYS = List.of("turret.station_outputs", "turret.strobe",
            "turret.in_position");

    private static Optional<Turret> turret(ProfileFile f, int tools, GalilModel model) throws TableException {
        ProfileFile.Entry given = null;
        String missing = null;
        for (String k : TURRET_KEYS) {
            if (f.entry(k).isPresent()) {
                given = given == null ? f.entry(k).get() : given;
            } else if (missing == null) {
                missing = k;
            }
        }
        if (given == null && f.entry("turret.timeout").isEmpty()) {
            return Optional.empty();
        }
        if (given == null || missing != null) {
            ProfileFile.Entry at = given != null ? given : f.entry("turret.timeout").get();
            throw f.fault(at, Code.E432_TURRET_INCOMPLETE, at.key(), missing != null ? missing : TURRET_KEYS.get(0));
        }
        ProfileFile.Entry outs = f.required("turret.station_outputs");
        List<Integer> bits = new ArrayList<>();
        for (String part : outs.value().split(",", -1)) {
            bits.add(bit(f, outs, part.strip()));
        }
        if (bits.size() > 8 || (1 << bits.size()) - 1 < tools) {
            throw f.fault(outs, Code.E433_TURRET_STATIONS, bits.size(), (1 << Math.min(bits.size(), 30)) - 1, tools);
        }
        for (int b : bits) {
            output(f, outs, b, model);
        }
        int strobe = bit(f, f.required("turret.strobe"), f.required("turret.strobe").value().strip());
        output(f, f.required("turret.strobe"), strobe, model);
        ProfileFile.Entry in = f.required("turret.in_position");
        int input = input(f, in, in.value().strip(), model);
        double timeout = f.entry("turret.timeout").isPresent() ? f.within("turret.timeout", 0.1, 600) : DEFAULT_TIMEOUT;
        return Optional.of(new Turret(bits, strobe, input, timeout));
    }

    private static Homing homing(ProfileFile f, GalilModel model) throws TableException {
        double tolerance = f.entry("homing.tolerance").isPresent() ? f.within("homing.tolerance", 0.001, 10)
                : DEFAULT_TOLERANCE_MM;
        Optional<ProfileFile.Entry> e = f.entry("homing.check");
        if (e.isEmpty()) {
            return new Homing.Position(tolerance);
        }
        String v = e.get().value().strip();
        Matcher m = INPUT.matcher(v);
        if (m.matches()) {
            return new Homing.Input(input(f, e.get(), m.group(1), model));
        }
        if (v.equalsIgnoreCase("position")) {
            return new Homing.Position(tolerance);
        }
        if (v.equalsIgnoreCase("none")) {
            return new Homing.None();
        }
        throw f.fault(e.get(), Code.E434_HOMING_CHECK, v);
    }

    /** An output the model has, as the M codes' outputs must be (E424, GalilModels). */
    private static void output(ProfileFile f, ProfileFile.Entry e, int bit, GalilModel model) throws TableException {
        if (bit > model.digitalOutputs()) {
            throw f.fault(e, Code.E424_OUTPUT_BEYOND_MODEL, e.key(), String.valueOf(bit), model.name(),
                    model.digitalOutputs());
        }
    }

    /** A digital input {@code @IN[n]} reads on {@code model} (see {@link #MIN_AUX_INPUT}), else E436 at the key. */
    private static int input(ProfileFile f, ProfileFile.Entry e, String digits, GalilModel model) throws TableException {
        int n = digits.matches("[0-9]{1,5}") ? Integer.parseInt(digits) : -1;
        boolean general = n >= 1 && n <= model.digitalOutputs();
        boolean aux = n >= MIN_AUX_INPUT && n <= MAX_AUX_INPUT;
        boolean modbus = n >= MIN_ANALOG && n <= MAX_ANALOG;
        if (!general && !aux && !modbus) {
            throw f.fault(e, Code.E436_INPUT_RANGE, e.key(), e.value().strip(), String.valueOf(model.digitalOutputs()),
                    model.name());
        }
        return n;
    }

    private static boolean bit(String digits) {
        int n = Integer.parseInt(digits);
        return n >= 1 && n <= MAX_BIT;
    }

    /** An input or output number 1 to 999 written in the value of {@code e}. */
    private static int bit(ProfileFile f, ProfileFile.Entry e, String text) throws TableException {
        if (!text.matches("[0-9]{1,3}") || !bit(text)) {
            throw f.fault(e, Code.E402_PROFILE_VALUE_RANGE, e.key(), text, 1, MAX_BIT);
        }
        return Integer.parseInt(text);
    }
}
