package gcnc.galil;

import gcnc.machine.MachineModel;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The Galil comment that records the blank a program was verified against,
 * {@code NO STOCK D<diameter> L<length> S<stickout>} in mm, or {@code NO STOCK NONE} when it was
 * verified without one (docs/dmc-format.md): written after the header when the program or the
 * user gave a blank or said there is none, read back by a replay of the DMC by itself.
 */
public final class StockComment {
    private static final Pattern FORM = Pattern.compile("NO STOCK D([0-9]+(?:\\.[0-9]+)?) L([0-9]+(?:\\.[0-9]+)?)"
            + " S(-?[0-9]+(?:\\.[0-9]+)?)(?: B([0-9]+(?:\\.[0-9]+)?))?");

    private StockComment() {
    }

    /** The comment of a program verified without a blank. */
    public static final String NONE = "NO STOCK NONE";

    public static String write(MachineModel.Blank b) {
        return "NO STOCK D" + GalilNumbers.angle(b.diameter()) + " L" + GalilNumbers.angle(b.length())
                + " S" + GalilNumbers.angle(b.stickout()) + (b.bore() > 0 ? " B" + GalilNumbers.angle(b.bore()) : "");
    }

    /** Whether the line says the program was verified without a blank. */
    public static boolean isNone(String line) {
        return line.strip().equals(NONE);
    }

    /** The blank of a {@code NO STOCK} comment, or null when the line is not one. */
    public static MachineModel.Blank read(String line) {
        Matcher m = FORM.matcher(line.strip());
        if (!m.matches()) {
            return null;
        }
        double bore = m.group(4) == null ? 0 : Double.parseDouble(m.group(4));
        if (!(bore < Double.parseDouble(m.group(1)))) {
            return null; // a bore as wide as the blank: not a comment gcnc writes
        }
        return new MachineModel.Blank(Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2)),
                Double.parseDouble(m.group(3)), bore);
    }
}
