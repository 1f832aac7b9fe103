package gcnc.cli;

import gcnc.StockText;
import gcnc.machine.MachineProfile;
import gcnc.sim.SimOptions;
import java.util.Optional;
import picocli.CommandLine.Option;

/**
 * The blank the simulator starts from: {@code --stock}. Without it the library ({@code
 * Compiler}) takes the program's stock header (an EMCO-style first-line comment {@code (length
 * diameter ...)}), else the profile's default, the same for every front end.
 */
final class StockOptions {
    /** A --stock value that is not three (or two) positive numbers. */
    static final class BadStock extends Exception {
        BadStock(String message) {
            super(message);
        }
    }

    @Option(names = "--stock", paramLabel = "DIA,LENGTH[,STICKOUT[,BORE]]",
            description = "Blank for the simulation: diameter, length, stick-out from the jaws and the"
                    + " diameter of a bore through it (a tube), each with its unit (1.75in, 44.45mm) or in the program's"
                    + " units when it says G20 or G21 before its first move (else mm);"
                    + " none: no blank (a second operation, a casting), the stock checks skipped.")
    String stock;

    /** What a value without a unit was read as, said on standard error; null when every value had its unit. */
    private String unitsNote;

    /**
     * The blank for {@code program} ({@code null}: standard input, which cannot be looked at first):
     * a value without a unit is in the program's units when its head says G20 or G21
     * ({@link gcnc.ProgramUnits}), else millimetres ({@link StockText}, as the Gradle plugin's
     * {@code stock} reads it); {@link #unitsNote} says which.
     */
    SimOptions options(MachineProfile profile, java.nio.file.Path program, Phrases say) throws BadStock {
        unitsNote = null;
        if (stock == null) {
            return SimOptions.defaults();
        }
        StockText.Read read;
        try {
            read = StockText.read("--stock", stock, profile, program);
        } catch (StockText.Bad e) {
            throw new BadStock(e.getMessage());
        }
        if (read.unitless()) {
            String units = say.get(read.inch() ? "stock.inches" : "stock.millimetres");
            unitsNote = read.declared().map(d -> say.get("stock.units.program", stock, units, d.word(), d.line()))
                    .orElseGet(() -> say.get(program == null ? "stock.units.stdin" : "stock.units.none", stock, units));
        }
        return read.options();
    }

    /** The line that says what a value without a unit was read as (the last {@link #options}), if any. */
    Optional<String> unitsNote() {
        return Optional.ofNullable(unitsNote);
    }
}
