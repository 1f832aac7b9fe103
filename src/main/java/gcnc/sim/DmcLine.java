package gcnc.sim;

/**
 * One DMC line as the simulator replays it: the text and the G-code source line it came from
 * (0 for header and footer lines). The lead adapts {@code gcnc.galil.GalilLine} to this record.
 */
public record DmcLine(String text, int sourceLine) {
}
