package gcnc.ir;

/**
 * The feed of a cutting move: the F word as programmed (the thesis dialect prints F x factor),
 * and the path speed the machine must run, in counts per second, with G94/G95/G98/G99 and the
 * spindle speed already applied.
 */
public record Feed(double programmed, double countsPerSecond) {
}
