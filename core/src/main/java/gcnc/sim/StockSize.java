package gcnc.sim;

/**
 * A blank as the machine profile or a program's stock header gives it, in the profile's
 * millimetres: diameter, overall length, and how far it sticks out of the chuck jaws' face.
 */
public record StockSize(double diameter, double length, double stickout) {
}
