package gcnc.controller;

/**
 * One VP or CR in the vector buffer: its number in its sequence (from 1; {@code _CSS} reads one less
 * while it executes), where it starts and ends (absolute positions of the two plane axes, counts), an
 * arc's centre, radius, start angle and signed sweep (radians), its length, its {@code <o} and
 * {@code >p} speeds (NaN when not given), and ({@code global}) its number among all segments executed
 * since power-up, 0 while it waits: what the stall and limit faults count.
 */
record VectorSegment(int number, boolean arc, double from1, double from2, double end1, double end2,
                     double centre1, double centre2, double radius, double startRad, double sweepRad, double length,
                     double o, double p, long global) {
    double at1(double s) {
        return arc ? centre1 + radius * Math.cos(startRad + sweepRad * s / length)
                : from1 + (end1 - from1) * s / length;
    }

    double at2(double s) {
        return arc ? centre2 + radius * Math.sin(startRad + sweepRad * s / length)
                : from2 + (end2 - from2) * s / length;
    }
}
