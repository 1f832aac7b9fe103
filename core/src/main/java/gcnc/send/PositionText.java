package gcnc.send;

import java.util.Locale;

/**
 * A position of the axes as a refusal or a resume advice gives it: in program terms first (X as
 * the block writes it, a diameter where the machine takes one, Z from work zero, in the block's
 * units, from its {@link BlockTable} frame), then the Galil counts of the plane in parentheses:
 * {@code X40.000 Z2.000 (Galil counts 147589,23634)}. Without a frame (the program could not be
 * read again) only the counts.
 */
record PositionText(DmcProgram program, BlockTable blocks) {

    /** {@code galil} (plane coordinates) in the terms of G-code line {@code line}, then its counts. */
    String at(int line, double[] galil) {
        double[] p = program(line, galil);
        if (p == null) {
            return counts(galil) + " (Galil counts)";
        }
        String f = blocks.at(line).inch() ? "%.4f" : "%.3f";
        return String.format(Locale.ROOT, "X" + f + " Z" + f, p[0], p[1]) + " (Galil counts " + counts(galil) + ")";
    }

    /** {@code galil} in line {@code line}'s program coordinates, or null when it has no frame. */
    double[] program(int line, double[] galil) {
        BlockTable.Block b = blocks.at(line);
        return b == null ? null : b.program(program.plane().machine(galil));
    }

    /** Whole counts of a point of the plane: {@code 147589,23634}. */
    static String counts(double[] p) {
        return Math.round(p[0]) + "," + Math.round(p[1]);
    }
}
