package gcnc.ir;

/**
 * The feed of a cutting move: the F word as programmed (the thesis dialect prints F x factor),
 * and the path speed the machine must run, in counts per second, with G94/G95/G98/G99 and the
 * spindle speed already applied. {@code perRevolution} says how F was read (G95/G99, and a
 * thread's lead; else per minute), so that the F can be named with its unit (gcnc path).
 */
public record Feed(double programmed, double countsPerSecond, boolean perRevolution) {
    /** A feed per minute. */
    public Feed(double programmed, double countsPerSecond) {
        this(programmed, countsPerSecond, false);
    }
}
