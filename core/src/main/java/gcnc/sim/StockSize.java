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

    /** A bar: no bore. */
    public StockSize(double diameter, double length, double stickout) {
        this(diameter, length, stickout, 0);
    }
}
