package gcnc.sim;

import gcnc.machine.Units;

/**
 * Where the tool tip went, as the program writes coordinates: X as the program writes it (a
 * diameter where the profile reads X as one, else a radius), Z from work zero, in the program's
 * units. Each move is measured in the frame of its own block (work offset, tool offset, G50/G92
 * shift), so a G28 to the reference point is as far as the control's position display would say.
 * The machine-frame envelope ({@link SimReport#xMinMm()} ...) stays beside it.
 *
 * @param units    the program's units: those of its first move (a program switching G20/G21 is
 *                 given in the first one's, every move converted)
 * @param diameter whether X is a diameter (the profile's {@code x.programming})
 */
public record ProgramEnvelope(Units units, boolean diameter, double xMin, double xMax, double zMin, double zMax) {

    /** "mm" or "in". */
    public String unit() {
        return units == Units.INCH ? "in" : "mm";
    }

    /** "diameter" or "radius": what X is. */
    public String xMode() {
        return diameter ? "diameter" : "radius";
    }

    /** Whether every point of this envelope lies within the limits (program terms; NaN limits are open). */
    public boolean within(double xLo, double xHi, double zLo, double zHi) {
        return !(xMin < xLo || xMax > xHi || zMin < zLo || zMax > zHi);
    }
}
