package gcnc.cli;

import gcnc.machine.MachineModel;
import gcnc.machine.MachineProfile;
import gcnc.sim.SimOptions;
import gcnc.sim.StockSize;
import gcnc.tables.TableException;
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
     * ({@link gcnc.ProgramUnits}), else millimetres; {@link #unitsNote} says which.
     */
    SimOptions options(MachineProfile profile, java.nio.file.Path program, Phrases say) throws BadStock {
        SimOptions o = SimOptions.defaults();
        double stickout = profile.model().stock().map(MachineModel.Blank::stickout).orElse(0.0);
        unitsNote = null;
        if (stock != null && stock.strip().equalsIgnoreCase("none")) {
            return o.withoutBlank();
        }
        if (stock != null) {
            Optional<gcnc.ProgramUnits.Declared> declared = Optional.empty();
            if (unitless(stock) && program != null && java.nio.file.Files.isRegularFile(program)) {
                try (java.io.Reader in = gcnc.Session.decode(java.nio.file.Files.newInputStream(program))) {
                    declared = gcnc.ProgramUnits.of(in, profile.control());
                } catch (java.io.IOException e) {
                    declared = Optional.empty(); // the program's own read reports it
                }
            }
            boolean inch = declared.map(d -> d.units() == gcnc.machine.Units.INCH).orElse(false);
            StockSize s = parse(stock, stickout, inch);
            if (unitless(stock)) {
                String units = say.get(inch ? "stock.inches" : "stock.millimetres");
                unitsNote = declared.map(d -> say.get("stock.units.program", stock, units, d.word(), d.line()))
                        .orElseGet(() -> say.get(program == null ? "stock.units.stdin" : "stock.units.none", stock, units));
            }
            Optional<StockSize.Beyond> beyond = s.beyond(profile);
            if (beyond.isPresent()) {
                throw new BadStock(beyondMessage(beyond.get(), profile));
            }
            return o.withStock(s);
        }
        return o;
    }

    /** The line that says what a value without a unit was read as (the last {@link #options}), if any. */
    Optional<String> unitsNote() {
        return Optional.ofNullable(unitsNote);
    }

    /** Whether some value of {@code text} has no unit. */
    static boolean unitless(String text) {
        for (String part : text.split(",")) {
            String v = part.strip().toLowerCase(java.util.Locale.ROOT);
            if (!(v.endsWith("in") || v.endsWith("\"") || v.endsWith("mm"))) {
                return true;
            }
        }
        return false;
    }

    /** What --stock says of a size the machine cannot hold (the simulation's E511-E513, as a usage error). */
    static String beyondMessage(StockSize.Beyond b, MachineProfile profile) {
        String what = switch (b.code()) {
            case E511_BLANK_TOO_WIDE -> "the diameter " + StockSize.shown(b.value()) + " mm is more than twice the X travel's"
                    + " reach from the centre line";
            case E512_BLANK_STICKS_OUT_TOO_FAR -> "the stick-out " + StockSize.shown(b.value()) + " mm is more than the Z travel's"
                    + " length";
            default -> "the length " + StockSize.shown(b.value()) + " mm is more than " + (int) StockSize.LENGTH_PER_Z_TRAVEL
                    + " times the Z travel's length";
        };
        return "--stock: " + what + " on machine " + profile.name() + ": at most " + StockSize.shown(b.limit()) + " mm ("
                + b.code().id() + ")";
    }

    /**
     * {@code DIA,LENGTH[,STICKOUT[,BORE]]}, each value millimetres, or with its unit: {@code 1.75in}
     * (also {@code 1.75"}) or {@code 44.45mm}, so a bar bought in inches is given as it is named
     * ({@code --stock 1.75in,4in,2in}). A value without a unit is in inches when {@code inch} (the
     * program says G20), else millimetres; the command says which on standard error, so that a number
     * read as inches in one program and as millimetres in the next is never silent.
     */
    static StockSize parse(String text, double defaultStickout, boolean inch) throws BadStock {
        String[] parts = text.split(",");
        if (parts.length < 2 || parts.length > 4) {
            throw new BadStock("--stock takes DIA,LENGTH, DIA,LENGTH,STICKOUT or DIA,LENGTH,STICKOUT,BORE in mm"
                    + " (or each with its unit: 1.75in, 44.45mm), not '" + text + "'");
        }
        double[] v = new double[4];
        v[2] = defaultStickout;
        for (int i = 0; i < parts.length; i++) {
            v[i] = millimetres(parts[i].trim(), inch);
            if (!(v[i] > 0) || !Double.isFinite(v[i])) {
                throw new BadStock("--stock: every value must be a number greater than 0");
            }
        }
        if (v[3] >= v[0]) {
            throw new BadStock("--stock: the bore " + parts[3].trim() + " must be smaller than the diameter " + parts[0].trim());
        }
        return new StockSize(v[0], v[1], v[2], v[3]);
    }

    /** One value of --stock in mm: {@code 50.8mm}, {@code 2in}, {@code 2"}; {@code 50.8} in inches when {@code inchDefault}. */
    private static double millimetres(String value, boolean inchDefault) throws BadStock {
        String v = value.toLowerCase(java.util.Locale.ROOT);
        boolean inch = inchDefault;
        if (v.endsWith("in") || v.endsWith("\"")) {
            inch = true;
            v = v.substring(0, v.length() - (v.endsWith("in") ? 2 : 1)).strip();
        } else if (v.endsWith("mm")) {
            inch = false;
            v = v.substring(0, v.length() - 2).strip();
        }
        try {
            double d = Double.parseDouble(v);
            // decimal arithmetic: 1.75in is 44.45 mm, not 44.449999999999996
            return inch && Double.isFinite(d) ? new java.math.BigDecimal(v).multiply(new java.math.BigDecimal("25.4")).doubleValue() : d;
        } catch (NumberFormatException e) {
            throw new BadStock("--stock: '" + value + "' is not a length (a number in mm, or with its unit: 1.75in, 44.45mm)");
        }
    }
}
