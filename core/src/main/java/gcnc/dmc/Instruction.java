package gcnc.dmc;

/** One DMC command and where it came from: what the backend hands on, one printed line each. */
public record Instruction(Command command, Source source) {
    public Instruction {
        java.util.Objects.requireNonNull(command);
        java.util.Objects.requireNonNull(source);
    }

    /** The DMC line it prints as ({@link DmcPrinter}): for front ends and tests that show text. */
    public String text() {
        return DmcPrinter.print(command);
    }
}
