package gcnc.sim;

/**
 * A blank as the machine profile, a program's stock header or {@code --stock} gives it, in the
 * profile's millimetres: diameter, overall length, how far it sticks out of the chuck jaws' face,
 * and the diameter of a bore through it (a tube, a part bored or drilled before; 0 for a bar).
 */
public record StockSize(double diameter, double length, double stickout, double bore) {
    public StockSize {
        if (!(bore >= 0 && bore < diameter)) {
            throw new IllegalArgumentException("a bore is 0 or more and less than the diameter: " + bore);
        }
    }

    /**
     * How many times the Z travel's length a blank may be: a bar reaches back through the spindle to
     * a bar feeder, so it may be longer than the travel, but not by this much (the material is
     * modelled along its whole length: {@code --stock 40,1e9} once filled a 6 GB heap).
     */
    public static final double LENGTH_PER_Z_TRAVEL = 10;

    /**
     * A size the machine cannot hold: which code says so, the size written and the most the machine
     * takes, both in mm.
     */
    public record Beyond(gcnc.diag.Code code, double value, double limit) {
    }

    /**
     * The first size of this blank that {@code profile}'s machine cannot hold, or empty: a diameter
     * past twice the X travel's reach from the centre line (E511; a tool could not reach its
     * outside), a stick-out past the Z travel's length (E512), a length past {@link
     * #LENGTH_PER_Z_TRAVEL} times it (E513). A number too large to be one (1e999) is past all of them.
     */
    public java.util.Optional<Beyond> beyond(gcnc.machine.MachineProfile profile) {
        gcnc.machine.Axis x = profile.x();
        gcnc.machine.Axis z = profile.z();
        double centre = profile.model().centreX();
        double reach = Math.max(Math.abs(x.min() / x.countsPerMm() - centre), Math.abs(x.max() / x.countsPerMm() - centre));
        double zTravel = Math.abs(z.max() - z.min()) / z.countsPerMm();
        if (!(diameter <= 2 * reach)) {
            return java.util.Optional.of(new Beyond(gcnc.diag.Code.E511_BLANK_TOO_WIDE, diameter, 2 * reach));
        }
        if (!(stickout <= zTravel)) {
            return java.util.Optional.of(new Beyond(gcnc.diag.Code.E512_BLANK_STICKS_OUT_TOO_FAR, stickout, zTravel));
        }
        if (!(length <= LENGTH_PER_Z_TRAVEL * zTravel)) {
            return java.util.Optional.of(new Beyond(gcnc.diag.Code.E513_BLANK_TOO_LONG, length, LENGTH_PER_Z_TRAVEL * zTravel));
        }
        return java.util.Optional.empty();
    }

    /** A size as a message shows it: up to 3 decimals, a number past 10^15 mm in powers of ten (1e999 is Infinity). */
    public static String shown(double mm) {
        return Math.abs(mm) < 1e15 ? MotionChecks.mm(mm) : String.format(java.util.Locale.ROOT, "%.3e", mm);
    }

    /** A bar: no bore. */
    public StockSize(double diameter, double length, double stickout) {
        this(diameter, length, stickout, 0);
    }
}
