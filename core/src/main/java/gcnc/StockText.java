package gcnc;

import gcnc.machine.MachineModel;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import gcnc.sim.SimOptions;
import gcnc.sim.StockSize;
import java.io.IOException;
import java.io.Reader;
import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;

/**
 * The blank as a user writes it, the same for every front end that takes one: {@code gcnc compile
 * --stock 1.75in,4in,2in} and the Gradle plugin's {@code gcnc { stock = '1.75in,4in,2in' }}.
 * {@code DIA,LENGTH[,STICKOUT[,BORE]]}, each value with its unit ({@code 1.75in}, {@code 1.75"},
 * {@code 44.45mm}) or, without one, in the program's units when its head says G20 or G21
 * ({@link ProgramUnits}), else millimetres; {@code none}: no blank (a second operation, a casting).
 * A stick-out not given is the profile's blank's. Which setting a message names ({@code --stock},
 * {@code stock}) is the caller's.
 */
public final class StockText {
    /** A value that is not a blank, or a blank the machine cannot hold: the message names the setting. */
    public static final class Bad extends Exception {
        Bad(String message) {
            super(message);
        }
    }

    /**
     * What a value was read as: the simulation's start ({@code options}), the units the program
     * declared (looked for only when some value has no unit and the program is a file), and whether
     * a value without a unit was read as inches.
     */
    public record Read(SimOptions options, boolean unitless, Optional<ProgramUnits.Declared> declared, boolean inch) {
    }

    private StockText() {
    }

    /**
     * {@code text} (named {@code setting} in a message) for {@code program} on {@code profile}'s machine
     * ({@code program} null: standard input, which cannot be looked at first: a value without a unit is mm).
     */
    public static Read read(String setting, String text, MachineProfile profile, Path program) throws Bad {
        SimOptions o = SimOptions.defaults();
        if (text.strip().equalsIgnoreCase("none")) {
            return new Read(o.withoutBlank(), false, Optional.empty(), false);
        }
        double stickout = profile.model().stock().map(MachineModel.Blank::stickout).orElse(0.0);
        boolean unitless = unitless(text);
        Optional<ProgramUnits.Declared> declared = Optional.empty();
        if (unitless && program != null && Files.isRegularFile(program)) {
            try (Reader in = Session.decode(Files.newInputStream(program))) {
                declared = ProgramUnits.of(in, profile.control());
            } catch (IOException e) {
                declared = Optional.empty(); // the program's own read reports it
            }
        }
        boolean inch = declared.map(d -> d.units() == Units.INCH).orElse(false);
        StockSize s = parse(setting, text, stickout, inch);
        Optional<StockSize.Beyond> beyond = s.beyond(profile);
        if (beyond.isPresent()) {
            throw new Bad(beyondMessage(setting, beyond.get(), profile));
        }
        return new Read(o.withStock(s), unitless, declared, inch);
    }

    /** Whether some value of {@code text} has no unit. */
    public static boolean unitless(String text) {
        for (String part : text.split(",")) {
            String v = part.strip().toLowerCase(Locale.ROOT);
            if (!(v.endsWith("in") || v.endsWith("\"") || v.endsWith("mm"))) {
                return true;
            }
        }
        return false;
    }

    /** What the setting says of a size the machine cannot hold (the simulation's E511-E513, as a usage error). */
    static String beyondMessage(String setting, StockSize.Beyond b, MachineProfile profile) {
        String what = switch (b.code()) {
            case E511_BLANK_TOO_WIDE -> "the diameter " + StockSize.shown(b.value()) + " mm is more than twice the X travel's"
                    + " reach from the centre line";
            case E512_BLANK_STICKS_OUT_TOO_FAR -> "the stick-out " + StockSize.shown(b.value()) + " mm is more than the Z travel's"
                    + " length";
            default -> "the length " + StockSize.shown(b.value()) + " mm is more than " + (int) StockSize.LENGTH_PER_Z_TRAVEL
                    + " times the Z travel's length";
        };
        return setting + ": " + what + " on machine " + profile.name() + ": at most " + StockSize.shown(b.limit()) + " mm ("
                + b.code().id() + ")";
    }

    /**
     * {@code DIA,LENGTH[,STICKOUT[,BORE]]}, each value millimetres, or with its unit: {@code 1.75in}
     * (also {@code 1.75"}) or {@code 44.45mm}, so a bar bought in inches is given as it is named
     * ({@code --stock 1.75in,4in,2in}). A value without a unit is in inches when {@code inch} (the
     * program says G20), else millimetres; the front end says which, so that a number read as inches
     * in one program and as millimetres in the next is never silent.
     */
    public static StockSize parse(String setting, String text, double defaultStickout, boolean inch) throws Bad {
        String[] parts = text.split(",");
        if (parts.length < 2 || parts.length > 4) {
            throw new Bad(setting + " takes DIA,LENGTH, DIA,LENGTH,STICKOUT or DIA,LENGTH,STICKOUT,BORE in mm"
                    + " (or each with its unit: 1.75in, 44.45mm), not '" + text + "'");
        }
        double[] v = new double[4];
        v[2] = defaultStickout;
        for (int i = 0; i < parts.length; i++) {
            v[i] = millimetres(setting, parts[i].trim(), inch);
            if (!(v[i] > 0) || !Double.isFinite(v[i])) {
                throw new Bad(setting + ": every value must be a number greater than 0");
            }
        }
        if (v[3] >= v[0]) {
            throw new Bad(setting + ": the bore " + parts[3].trim() + " must be smaller than the diameter " + parts[0].trim());
        }
        return new StockSize(v[0], v[1], v[2], v[3]);
    }

    /** One value in mm: {@code 50.8mm}, {@code 2in}, {@code 2"}; {@code 50.8} in inches when {@code inchDefault}. */
    private static double millimetres(String setting, String value, boolean inchDefault) throws Bad {
        String v = value.toLowerCase(Locale.ROOT);
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
            return inch && Double.isFinite(d) ? new BigDecimal(v).multiply(new BigDecimal("25.4")).doubleValue() : d;
        } catch (NumberFormatException e) {
            throw new Bad(setting + ": '" + value + "' is not a length (a number in mm, or with its unit: 1.75in, 44.45mm)");
        }
    }
}
