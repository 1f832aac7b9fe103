package gcnc.check.geom;

import gcnc.check.BlockDraft;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;

/**
 * The spindle speed during a block. G97: the rpm of the last S. G96: rpm = 1000 V / (pi D)
 * (V m/min, D mm; in G20 V is ft/min, 304.8 mm per foot) at the block's end diameter, clamped
 * by G50 S and the machine maximum (D = 0 gives the clamp).
 */
public final class SpindleSpeed {
    private final MachineProfile p;
    private final Coordinates c;

    public SpindleSpeed(MachineProfile p, Coordinates c) {
        this.p = p;
        this.c = c;
    }

    public double rpm(BlockDraft d, Point end) {
        if (!d.next.css || Double.isNaN(d.next.surfaceSpeed)) {
            return d.next.rpm;
        }
        double perUnit = d.units == Units.INCH ? 304.8 : 1000;
        double dia = c.diameterMm(end, d.next);
        double rpm = dia > 0 ? perUnit * d.next.surfaceSpeed / (Math.PI * dia) : Double.POSITIVE_INFINITY;
        double clamp = Double.isNaN(d.next.rpmClamp) ? p.maxRpm() : Math.min(d.next.rpmClamp, p.maxRpm());
        return Math.min(rpm, clamp);
    }
}
