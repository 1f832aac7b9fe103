package gcnc.galil;

/** One line of DMC output and the G-code line it came from (0 for the program header and footer). */
public record GalilLine(String text, int sourceLine) {
}
