package gcnc.sim;

import java.util.List;
import java.util.Optional;

/**
 * What a setup person needs from a run besides the findings (a setup sheet's head): the blank as
 * it was simulated, where the work zero stood, the tools in the order they were first used, and the
 * highest spindle speed.
 *
 * @param blank        the blank simulated (diameter, length, stick-out from the jaws' face), empty
 *                     when there was none
 * @param chuckFaceMm  machine Z of the jaws' front face, NaN when the profile has no chuck
 * @param workZeroXMm  machine X (radius from machine X zero, mm) of the work zero of the first cut
 *                     (work offset + tool offset + G50/G92 shift of the first feed move's block;
 *                     of the first move when nothing fed), NaN when not known (a bare DMC replay)
 * @param workZeroZMm  machine Z of the same work zero, mm
 * @param maxRpm       the highest spindle speed the DMC set, r/min; NaN when not known
 * @param tools        every station that moved, in the order of first use
 */
public record SetupFacts(Optional<StockSize> blank, double chuckFaceMm, double workZeroXMm, double workZeroZMm,
                         double maxRpm, List<ToolUse> tools) {
    public SetupFacts {
        tools = List.copyOf(tools);
    }

    /** The work zero's distance in front of the jaws' face, mm; NaN when either is not known. */
    public double workZeroFromFaceMm() {
        return workZeroZMm - chuckFaceMm;
    }
}
