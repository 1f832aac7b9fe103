package gcnc.sim;

/**
 * What a simulation found and measured.
 *
 * @param sequences     vector sequences replayed (one per motion)
 * @param segments      VP/CR segments replayed
 * @param findings      diagnostics the simulator reported (they are in the run's Diagnostics)
 * @param xMinMm        travel envelope of machine X (mm, a radius from machine X zero), NaN when nothing moved
 * @param xMaxMm        ...
 * @param zMinMm        travel envelope of machine Z (mm)
 * @param zMaxMm        ...
 * @param cycleSeconds  estimated run time: the speed profile of every segment (from its corner speed
 *                      to its own and down to the next corner, VA/VD) plus dwells
 * @param exactStopSeconds the same program with every motion stopped at its end: the difference is
 *                      what blending gains
 * @param drawing       the path and machine for an SVG, null unless {@link SimOptions#keepPath()}
 * @param program       the same envelope as the program writes coordinates (X as written, Z from
 *                      work zero, the program's units): what a person reads first; null when the
 *                      program frame is not known (a DMC replayed by itself) or nothing moved
 * @param feeds         the envelope of the feed moves alone, in the same terms: where the part is cut,
 *                      apart from the rapids and the home moves (G28, G53) that reach out to the
 *                      reference point; null when no move fed
 * @param setup         the blank, the work zero, the tools used and the top speed, for a setup sheet
 * @param corners       the slowest corners of the blended sequences, slowest first (at most 100;
 *                      docs/galil.md, "The corner report")
 * @param stops         how many sequences ended for each reason the planner recorded ({@code gcnc.plan.Stop}'s
 *                      keys, in that enum's order); empty for a DMC read back, which does not carry them
 * @param programStops  the program stops replayed (M00, M01 with the optional stop switch on): each
 *                      waits for the operator, a wait {@link #cycleSeconds} does not count
 */
public record SimReport(int sequences, int segments, int findings, double xMinMm, double xMaxMm, double zMinMm,
                        double zMaxMm, double cycleSeconds, double exactStopSeconds, Drawing drawing,
                        ProgramEnvelope program, ProgramEnvelope feeds, SetupFacts setup, java.util.List<Corner> corners,
                        java.util.Map<String, Integer> stops, int programStops) {
    public SimReport {
        corners = java.util.List.copyOf(corners);
        stops = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(stops));
    }

    /** A report without corners. */
    public SimReport(int sequences, int segments, int findings, double xMinMm, double xMaxMm, double zMinMm,
                     double zMaxMm, double cycleSeconds, double exactStopSeconds, Drawing drawing,
                     ProgramEnvelope program, ProgramEnvelope feeds, SetupFacts setup) {
        this(sequences, segments, findings, xMinMm, xMaxMm, zMinMm, zMaxMm, cycleSeconds, exactStopSeconds, drawing,
                program, feeds, setup, java.util.List.of(), java.util.Map.of(), 0);
    }

    /** The same report with these corners (the {@code n} slowest of them, for {@code --corners n}). */
    public SimReport withCorners(java.util.List<Corner> slowest, int n) {
        return new SimReport(sequences, segments, findings, xMinMm, xMaxMm, zMinMm, zMaxMm, cycleSeconds,
                exactStopSeconds, drawing, program, feeds, setup, slowest.subList(0, Math.min(n, slowest.size())), stops,
                programStops);
    }

    /** The same report with these counts of stops by reason. */
    public SimReport withStops(java.util.Map<String, Integer> counts) {
        return new SimReport(sequences, segments, findings, xMinMm, xMaxMm, zMinMm, zMaxMm, cycleSeconds,
                exactStopSeconds, drawing, program, feeds, setup, corners, counts, programStops);
    }

    /** The same report with {@code n} more findings (a DMC file's own limit errors, found before its replay). */
    public SimReport withMoreFindings(int n) {
        return new SimReport(sequences, segments, findings + n, xMinMm, xMaxMm, zMinMm, zMaxMm, cycleSeconds,
                exactStopSeconds, drawing, program, feeds, setup, corners, stops, programStops);
    }

    /** The same report with this count of program stops. */
    public SimReport withProgramStops(int n) {
        return new SimReport(sequences, segments, findings, xMinMm, xMaxMm, zMinMm, zMaxMm, cycleSeconds,
                exactStopSeconds, drawing, program, feeds, setup, corners, stops, n);
    }
}
