package gcnc.machine;

import gcnc.diag.Code;
import gcnc.tables.TableException;
import java.util.Set;
import java.util.TreeSet;

/**
 * How the machine may blend consecutive moves (docs/galil.md, "Continuous contouring"): profile keys
 * {@code plan.blend} ({@code on}, the default: consecutive moves run as one vector sequence with
 * corner speeds; {@code off}: every move stops at its end), {@code corner.deviation}, mm (the
 * junction deviation of Grbl's planner: how far from the sharp corner a path of the corner speed
 * would pass, were the controller to round it; default 0.01 mm, the value Grbl ships) and
 * {@code plan.on_the_fly}: the M codes whose outputs may switch while the axes move, at the point
 * of the path where the program has them (default: the coolant codes M07, M08, M09 the control
 * has; {@code none}: every output stops the machine).
 */
public record Blending(boolean on, double deviationMm, Set<Integer> onTheFly) {
    public Blending {
        onTheFly = Set.copyOf(onTheFly);
    }

    /** The coolant codes (mist, flood, off) that switch on the fly unless the profile says otherwise. */
    static final int[] COOLANT = {7, 8, 9};

    /** The defaults for a profile without the keys, on control {@code c}. */
    public static Blending defaults(Control c) {
        return new Blending(true, 0.01, coolant(c));
    }

    /** Whether M code {@code m}'s outputs may switch while the axes move. */
    public boolean flies(int m) {
        return onTheFly.contains(m);
    }

    /** Reads and checks the keys (a fault at the key's line). */
    public static Blending read(ProfileFile f, Control c) throws TableException {
        boolean on = f.choice("plan.blend", "on", "on", "off").equals("on");
        double deviation = f.entry("corner.deviation").isPresent() ? f.within("corner.deviation", 0.0001, 1) : 0.01;
        return new Blending(on, deviation, onTheFly(f, c));
    }

    /**
     * {@code plan.on_the_fly = M07 M08 M09} (spaces or commas; {@code none}: no M code). Only an M
     * whose function is {@code output} in the control's table may switch on the fly: a spindle or
     * chuck code, a stop, an end or a call must happen with the axes at rest (E253).
     */
    private static Set<Integer> onTheFly(ProfileFile f, Control c) throws TableException {
        var e = f.entry("plan.on_the_fly");
        if (e.isEmpty()) {
            return coolant(c);
        }
        Set<Integer> codes = new TreeSet<>();
        String v = e.get().value().strip();
        if (v.equalsIgnoreCase("none")) {
            return codes;
        }
        for (String word : v.split("[\\s,]+")) {
            String digits = word.toUpperCase(java.util.Locale.ROOT).startsWith("M") ? word.substring(1) : word;
            MFunction m = digits.matches("[0-9]{1,3}") ? c.m().get(Integer.parseInt(digits)) : null;
            if (m == null || m.role() != MRole.OUTPUT) {
                throw f.fault(e.get(), Code.E253_ON_THE_FLY_NOT_OUTPUT, v, word, c.name(),
                        m == null ? "-" : m.role().name().toLowerCase(java.util.Locale.ROOT));
            }
            codes.add(m.code());
        }
        return codes;
    }

    private static Set<Integer> coolant(Control c) {
        Set<Integer> codes = new TreeSet<>();
        for (int m : COOLANT) {
            MFunction f = c.m().get(m);
            if (f != null && f.role() == MRole.OUTPUT) {
                codes.add(m);
            }
        }
        return codes;
    }

    /** The profile's blending, already checked when it was loaded. */
    public static Blending of(MachineProfile p) {
        try {
            return p.file() == null ? defaults(p.control()) : read(p.file(), p.control());
        } catch (TableException e) {
            throw new IllegalStateException("checked at load: " + e.getMessage(), e);
        }
    }

    /**
     * Grbl's junction-deviation speed of a corner (counts/s): {@code cos} is the cosine of the
     * angle between the incoming and the reversed outgoing direction (-1 straight on, +1 straight
     * back), for a machine of this {@code acceleration} (counts/s²) and {@code deviation} (counts).
     * Unbounded straight on, 0 straight back. The planner takes a share of it; the replay holds the
     * written corners to it (E332): one formula for both.
     */
    public static double junctionSpeed(double cos, double acceleration, double deviation) {
        if (cos < -0.999999) {
            return Double.POSITIVE_INFINITY;
        }
        if (cos > 0.999999) {
            return 0;
        }
        double sinHalf = Math.sqrt(0.5 * (1 - cos));
        return Math.sqrt(acceleration * deviation * sinHalf / (1 - sinHalf));
    }
}
