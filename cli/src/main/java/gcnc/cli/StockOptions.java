package gcnc.cli;

import gcnc.StockText;
import gcnc.machine.MachineProfile;
import gcnc.sim.SimOptions;
import java.nio.file.Path;
import java.util.function.Consumer;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;

/**
 * The blank the simulator starts from: {@code --stock}. Without it the library ({@code
 * Compiler}) takes the program's stock header (an EMCO-style first-line comment {@code (length
 * diameter ...)}), else the profile's default, the same for every front end.
 */
final class StockOptions {
    @Option(names = "--stock", paramLabel = "DIA,LENGTH[,STICKOUT[,BORE]]",
            description = "Blank for the simulation: diameter, length, stick-out from the jaws and the"
                    + " diameter of a bore through it (a tube), each with its unit (1.75in, 44.45mm) or in the program's"
                    + " units when it says G20 or G21 before its first move (else mm);"
                    + " none: no blank (a second operation, a casting), the stock checks skipped.")
    String stock;

    /**
     * The blank for {@code file} ({@code -}: standard input, which cannot be looked at first): a value
     * without a unit is in the program's units when its head says G20 or G21 ({@link gcnc.ProgramUnits}),
     * else millimetres ({@link StockText}, as the Gradle plugin's {@code stock} reads it), and the line
     * that says which goes to {@code note}. A value that is not a blank, or one the machine cannot hold,
     * is the command's usage error ({@code spec}).
     */
    SimOptions options(MachineProfile profile, Path file, Phrases say, CommandSpec spec, Consumer<String> note) {
        if (stock == null) {
            return SimOptions.defaults();
        }
        Path program = SourceFiles.isStdin(file) ? null : file;
        StockText.Read read;
        try {
            read = StockText.read("--stock", stock, profile, program);
        } catch (StockText.Bad e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        if (read.unitless()) {
            String units = say.get(read.inch() ? "stock.inches" : "stock.millimetres");
            note.accept(read.declared().map(d -> say.get("stock.units.program", stock, units, d.word(), d.line()))
                    .orElseGet(() -> say.get(program == null ? "stock.units.stdin" : "stock.units.none", stock, units)));
        }
        return read.options();
    }
}
