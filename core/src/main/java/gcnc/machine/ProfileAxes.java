package gcnc.machine;

import static gcnc.machine.ProfileFile.written;

import gcnc.diag.Phrase;
import gcnc.ir.Point;
import gcnc.tables.TableException;

/**
 * The profile's axes and Galil channels, as {@link ProfileLoader} reads them: X and Z (channel, counts
 * per mm and per inch, sign, travel), the spindle's channel and encoder, machine positions inside the travel.
 */
final class ProfileAxes {
    private ProfileAxes() {
    }

    /**
     * Counts per mm gcnc takes: one count from 1 mm (the thesis machine has 1.5 counts per mm)
     * down to 1 nm; outside that a value is a slip (a zero too many or too few), E402.
     */
    static final double MIN_COUNTS_PER_MM = 1;

    static final double MAX_COUNTS_PER_MM = 1_000_000;

    /** The largest encoder resolution gcnc accepts: 2^20 counts per revolution. */
    static final int MAX_ENCODER_COUNTS = 1 << 20;

    /**
     * {@code spindle.encoder} (counts per revolution, a whole number 4 to 2^20) and
     * {@code spindle.encoder_axis} (the channel whose main encoder reads it, by default
     * {@code spindle.axis}; not a channel that moves the tool); null when the profile has none.
     */
    static SpindleEncoder encoder(ProfileFile f, Axis x, Axis z) throws TableException {
        if (f.entry("spindle.encoder").isEmpty()) {
            if (f.entry("spindle.encoder_axis").isPresent()) {
                throw f.fault(f.required("spindle.encoder_axis"),
                        Phrase.ENCODER_AXIS_NEEDS_ENCODER.arg());
            }
            return null;
        }
        ProfileFile.Entry e = f.required("spindle.encoder");
        double counts = f.number(e);
        if (counts != Math.rint(counts) || counts < 4 || counts > MAX_ENCODER_COUNTS) {
            throw f.fault(e, Phrase.ENCODER_COUNTS.with(MAX_ENCODER_COUNTS));
        }
        char channel = channelLetter(f, "spindle.encoder_axis", f.text("spindle.axis", "C"));
        for (Axis a : new Axis[] {x, z}) {
            if (Plane.channel(channel) == Plane.channel(a.galil())) {
                throw f.fault(f.entry("spindle.encoder_axis").orElse(e), Phrase.ENCODER_ON_TOOL_AXIS.with(channel,
                        a == x ? "X" : "Z", a == x ? "x" : "z", a.galil()));
            }
        }
        return new SpindleEncoder((int) counts, channel);
    }

    static Axis axis(ProfileFile f, String a) throws TableException {
        char letter = channelLetter(f, a + ".galil", null);
        double perMm = f.within(a + ".counts_per_mm", MIN_COUNTS_PER_MM, MAX_COUNTS_PER_MM);
        double perInch = f.entry(a + ".counts_per_inch").isPresent()
                ? f.within(a + ".counts_per_inch", MIN_COUNTS_PER_MM * 25.4, MAX_COUNTS_PER_MM * 25.4) : perMm * 25.4;
        double sign = f.number(a + ".sign", 1);
        if (sign != 1 && sign != -1) {
            throw f.fault(f.required(a + ".sign"), Phrase.SIGN.with(a));
        }
        ProfileFile.Entry te = f.required(a + ".travel");
        double[] travel = f.pair(te);
        if (travel[0] >= travel[1]) {
            throw f.fault(te, Phrase.TRAVEL_ORDER.with(a, "min, max"));
        }
        for (double end : travel) {
            if (Math.abs(end * perMm) > ProfileLoader.REGISTER_MAX) {
                throw f.fault(te, Phrase.TRAVEL_REGISTER.with(a, written(end),
                        written(Math.rint(end * perMm))));
            }
        }
        return new Axis(letter, perMm, perInch, (int) sign, travel[0] * perMm, travel[1] * perMm);
    }

    /** One Galil channel letter; {@code otherwise} when the key is absent (null: required). */
    static char channelLetter(ProfileFile f, String key, String otherwise) throws TableException {
        String letter = otherwise == null ? f.text(key) : f.text(key, otherwise);
        if (!letter.matches("[A-HXYZW]")) {
            throw f.fault(f.required(key), Phrase.CHANNEL_LETTER.with(key, "A-H, X, Y, Z, W"));
        }
        return letter.charAt(0);
    }

    /** The spindle's OF channel, which cannot be one of the two that move the tool. */
    static char spindleAxis(ProfileFile f, Axis x, Axis z) throws TableException {
        char s = channelLetter(f, "spindle.axis", "C");
        for (Axis a : new Axis[] {x, z}) {
            if (Plane.channel(s) == Plane.channel(a.galil())) {
                throw f.fault(f.required("spindle.axis"), Phrase.SPINDLE_ON_TOOL_AXIS.with(s,
                        a == x ? "X" : "Z", a == x ? "x" : "z", a.galil()));
            }
        }
        return s;
    }


    /**
     * A machine position {@code x, z} in mm (home, machine_zero), in counts. It must be inside the
     * travel: the machine cannot start at, or return to, a place its axes cannot reach.
     */
    static Point position(ProfileFile f, String key, Axis x, Axis z) throws TableException {
        ProfileFile.Entry e = f.required(key);
        double[] v = f.pair(e);
        inTravel(f, e, "x", v[0]);
        inTravel(f, e, "z", v[1]);
        return new Point(v[0] * x.countsPerMm(), v[1] * z.countsPerMm());
    }

    static void inTravel(ProfileFile f, ProfileFile.Entry e, String axis, double mm) throws TableException {
        double[] travel = f.pair(axis + ".travel");
        if (mm < travel[0] || mm > travel[1]) {
            throw f.fault(e, Phrase.OUTSIDE_TRAVEL.with(e.key(), axis.toUpperCase(), written(mm), axis,
                    written(travel[0]), written(travel[1])));
        }
    }
}
