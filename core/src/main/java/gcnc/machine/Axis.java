package gcnc.machine;

/**
 * One lathe axis as the machine drives it.
 *
 * @param galil          the Galil channel letter (X, Y, Z, W or A..H)
 * @param countsPerMm    encoder counts per millimetre of travel
 * @param countsPerInch  encoder counts per inch (the thesis's machine has 1200, not 1.5 x 25.4)
 * @param sign           +1 or -1: the direction Galil counts grow, relative to the machine's + direction
 * @param min            travel limit, machine counts
 * @param max            travel limit, machine counts
 */
public record Axis(char galil, double countsPerMm, double countsPerInch, int sign, double min, double max) {
    public double countsPer(Units u) {
        return u == Units.INCH ? countsPerInch : countsPerMm;
    }

    public boolean inTravel(double counts) {
        return counts >= min && counts <= max;
    }
}
