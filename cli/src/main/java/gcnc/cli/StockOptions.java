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
                    + " diameter of a bore through it (a tube), each in mm or with its unit (1.75in, 44.45mm);"
                    + " none: no blank (a second operation, a casting), the stock checks skipped.")
    String stock;

SimOptions options(MachineProfile profile) throws BadStock {
        SimOptions o = SimOptions.defaults();
        double stickout = profile.model().stock().map(MachineModel.Blank::stickout).orElse(0.0);
        if (stock != null && stock.strip().equalsIgnoreCase("none")) {
            return o.withoutBlank();
        }
        if (stock != null) {
            StockSize s = parse(stock, stickout);
            Optional<StockSize.Beyond> beyond = s.beyond(profile);
            if (beyond.isPresent()) {
                throw new BadStock(beyondMessage(beyond.get(), profile));
            }
            return o.withStock(s);
        }
        return o;
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
     * ({@code --stock 1.75in,4in,2in}). A value without a unit is millimetres, whatever the
     * program's units: the option is read before the program, and a number that meant inches in one
     * program and millimetres in the next would be a trap.
     */
    static StockSize parse(String text, double defaultStickout) throws BadStock {
        String[] parts = text.split(",");
        if (parts.length < 2 || parts.length > 4) {
            throw new BadStock("--stock takes DIA,LENGTH, DIA,LENGTH,STICKOUT or DIA,LENGTH,STICKOUT,BORE in mm"
                    + " (or each with its unit: 1.75in, 44.45mm), not '" + text + "'");
        }
        double[] v = new double[4];
        v[2] = defaultStickout;
        for (int i = 0; i < parts.length; i++) {
            v[i] = millimetres(parts[i].trim());
            if (!(v[i] > 0) || !Double.isFinite(v[i])) {
                throw new BadStock("--stock: every value must be a number greater than 0");
            }
        }
        if (v[3] >= v[0]) {
            throw new BadStock("--stock: the bore " + parts[3].trim() + " must be smaller than the diameter " + parts[0].trim());
        }
        return new StockSize(v[0], v[1], v[2], v[3]);
    }

    /** One value of --stock in mm: {@code 50.8}, {@code 50.8mm}, {@code 2in}, {@code 2"}. */
    private static double millimetres(String value) throws BadStock {
        String v = value.toLowerCase(java.util.Locale.ROOT);
        boolean inch = false;
        if (v.endsWith("in") || v.endsWith("\"")) {
            inch = true;
            v = v.substring(0, v.length() - (v.endsWith("in") ? 2 : 1)).strip();
        } else if (v.endsWith("mm")) {
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
