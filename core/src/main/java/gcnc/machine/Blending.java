package gcnc.machine;

import gcnc.tables.TableException;

/**
 * How the machine may blend consecutive moves (docs/galil.md, "Continuous contouring"): profile keys
 * {@code plan.blend} ({@code on}, the default: consecutive moves run as one vector sequence with
 * corner speeds; {@code off}: every move stops at its end) and {@code corner.deviation}, mm (the
 * junction deviation of Grbl's planner: how far from the sharp corner a path of the corner speed
 * would pass, were the controller to round it; default 0.01 mm, the value Grbl ships).
 */
public record Blending(boolean on, double deviationMm) {
    public static final Blending DEFAULT = new Blending(true, 0.01);

    /** Reads and checks the keys (a fault at the key's line). */
    public static Blending read(ProfileFile f) throws TableException {
        boolean on = f.choice("plan.blend", "on", "on", "off").equals("on");
        double deviation = f.entry("corner.deviation").isPresent() ? f.within("corner.deviation", 0.0001, 1)
                : DEFAULT.deviationMm;
        return new Blending(on, deviation);
    }

    /** The profile's blending, already checked when it was loaded. */
    public static Blending of(MachineProfile p) {
        try {
            return p.file() == null ? DEFAULT : read(p.file());
        } catch (TableException e) {
            throw new IllegalStateException("checked at load: " + e.getMessage(), e);
        }
    }
}
