package gcnc.studio;

import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.machine.Units;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.List;

/**
 * Configure's lengths in the program's terms: in the program's units, X as the program writes it (a
 * diameter where the profile reads X as one), beside the profile's own keys and values. A profile
 * holds travel in machine millimetres (X a radius) and offsets in its {@code offsets.unit}; a setup
 * person reads and types the numbers of the program and the control's offset page. Only the scale
 * changes, never the origin: a travel stays where the machine's axes end, an offset where the
 * profile puts it.
 *
 * <p>Back to the file the conversion is exact (decimal arithmetic: 16 in on a diameter is 203.2 mm
 * of radius, not 203.19999999999999), and a part of a value the page sends back as it was shown
 * keeps the file's own text: a round trip never drifts. The inch is 25.4 mm, unless the profile's
 * {@code counts_per_inch} and {@code counts_per_mm} say otherwise (the thesis's 1200 counts per inch
 * against 1.5 per mm: its inch is 800 of its millimetres, as a G20 program on it moves); a profile
 * whose two constants agree with 25.4 to a millionth writes 25.4 rounded (Haas: 984.2519685 and
 * 25000).
 */
final class ProfileTerms {
    /** Decimals a program-terms value is shown with, at most (trailing zeros dropped). */
    static final int SHOWN = 6;
    /** Decimals a value written back into the file keeps, at most: below a nanometre. */
    static final int WRITTEN = 9;
    private static final BigDecimal INCH = new BigDecimal("25.4");

    /** How one number of a key's value converts: an axis's length, X's doubled on a diameter; or not at all. */
    private record Part(char axis, boolean doubled, boolean counts) {
    }

    private final Units units;
    private final boolean diameter;
    private final boolean offsetsInCounts;
    /** For X and Z: file units per program unit, for a value in mm and for one in counts. */
    private final BigDecimal[] mmPer = new BigDecimal[2];
    private final BigDecimal[] countsPer = new BigDecimal[2];

    private ProfileTerms(Units units, boolean diameter, boolean offsetsInCounts) {
        this.units = units;
        this.diameter = diameter;
        this.offsetsInCounts = offsetsInCounts;
    }

    /** The terms of a program in {@code units} on the profile {@code p}, as its file {@code f} writes it. */
    static ProfileTerms of(MachineProfile p, ProfileFile f, Units units) {
        boolean counts = f.entry("offsets.unit").map(e -> e.value().equals("counts")).orElse(false);
        ProfileTerms t = new ProfileTerms(units, p.diameterX(), counts);
        String[] axes = {"x", "z"};
        gcnc.machine.Axis[] of = {p.x(), p.z()};
        for (int i = 0; i < 2; i++) {
            BigDecimal perMm = written(f, axes[i] + ".counts_per_mm", of[i].countsPerMm());
            if (units == Units.MM) {
                t.mmPer[i] = BigDecimal.ONE;
                t.countsPer[i] = perMm;
            } else {
                boolean given = f.entry(axes[i] + ".counts_per_inch").isPresent();
                BigDecimal perInch = given ? written(f, axes[i] + ".counts_per_inch", of[i].countsPerInch())
                        : perMm.multiply(INCH);
                BigDecimal ratio = perInch.divide(perMm, 20, RoundingMode.HALF_EVEN);
                boolean inch = ratio.subtract(INCH).abs().compareTo(new BigDecimal("0.0000254")) <= 0;
                t.mmPer[i] = inch ? INCH : ratio;
                t.countsPer[i] = perInch;
            }
        }
        return t;
    }

    /** A number as the file writes it (its own decimal text), else the loader's value. */
    private static BigDecimal written(ProfileFile f, String key, double loaded) {
        return f.entry(key).map(e -> number(e.value().strip())).orElse(BigDecimal.valueOf(loaded));
    }

    /** "mm" or "in". */
    String unit() {
        return units == Units.INCH ? "in" : "mm";
    }

    boolean diameter() {
        return diameter;
    }

    /** Whether a key's value is shown in program terms (the insert's outline, sim.tool.N, is not: it is its own text). */
    static boolean converted(String key) {
        return !key.startsWith("sim.tool.");
    }

    private List<Part> parts(String key) {
        if (key.equals("x.travel")) {
            return List.of(new Part('x', true, false), new Part('x', true, false));
        }
        if (key.equals("z.travel")) {
            return List.of(new Part('z', false, false), new Part('z', false, false));
        }
        if (key.startsWith("nose.")) { // a nose radius (a radius, whatever X is) and its tip direction (a number of its own)
            return List.of(new Part('x', false, offsetsInCounts), new Part(' ', false, false));
        }
        // work.G5x and tool.N: X and Z of a machine position or an offset, in offsets.unit
        return List.of(new Part('x', true, offsetsInCounts), new Part('z', false, offsetsInCounts));
    }

    /** File units per program unit of one part (null: a part not converted). */
    private BigDecimal per(Part p) {
        if (p.axis() == ' ') {
            return null;
        }
        int i = p.axis() == 'x' ? 0 : 1;
        BigDecimal per = p.counts() ? countsPer[i] : mmPer[i];
        return p.doubled() && diameter ? per.divide(BigDecimal.valueOf(2)) : per;
    }

    /** A file value ({@code a, b}) in program terms; each part that is not a number as written. */
    String shown(String key, String fileValue) {
        if (!converted(key) || fileValue.isBlank()) {
            return fileValue;
        }
        List<String> file = split(fileValue);
        List<Part> parts = parts(key);
        List<String> out = new ArrayList<>();
        for (int i = 0; i < file.size(); i++) {
            out.add(shownPart(i < parts.size() ? parts.get(i) : null, file.get(i)));
        }
        return String.join(", ", out);
    }

    private String shownPart(Part p, String filePart) {
        BigDecimal v = number(filePart);
        BigDecimal per = p == null ? null : per(p);
        if (v == null || per == null) {
            return filePart;
        }
        return plain(v.divide(per, SHOWN, RoundingMode.HALF_EVEN));
    }

    /**
     * A value typed in program terms back in the file's terms: each part converted exactly, except
     * a part given as {@link #shown} shows the file's, which keeps the file's own text.
     */
    String toFile(String key, String programValue, String fileValue) {
        if (!converted(key) || programValue.isBlank()) {
            return programValue.strip();
        }
        List<String> typed = split(programValue);
        while (typed.size() > 1 && typed.get(typed.size() - 1).isEmpty()) {
            typed.remove(typed.size() - 1);
        }
        List<String> file = fileValue.isBlank() ? List.of() : split(fileValue);
        List<Part> parts = parts(key);
        List<String> out = new ArrayList<>();
        for (int i = 0; i < typed.size(); i++) {
            Part p = i < parts.size() ? parts.get(i) : null;
            String was = i < file.size() ? file.get(i) : null;
            if (was != null && typed.get(i).equals(shownPart(p, was))) {
                out.add(was);
                continue;
            }
            BigDecimal v = number(typed.get(i));
            BigDecimal per = p == null ? null : per(p);
            out.add(v == null || per == null ? typed.get(i)
                    : plain(v.multiply(per).setScale(WRITTEN, RoundingMode.HALF_EVEN)));
        }
        return String.join(", ", out);
    }

    private static List<String> split(String value) {
        List<String> out = new ArrayList<>();
        for (String s : value.split(",", -1)) {
            out.add(s.strip());
        }
        return out;
    }

    /** A decimal number as a profile or a program writes one (1.5, -20, +3.), or null. */
    private static BigDecimal number(String text) {
        if (!text.matches("[+-]?([0-9]+\\.?[0-9]*|\\.[0-9]+)")) {
            return null;
        }
        return new BigDecimal(text.startsWith("+") ? text.substring(1) : text);
    }

    /** Without trailing zeros, never in exponent form: 203.2, -4, 0. */
    private static String plain(BigDecimal v) {
        BigDecimal s = v.stripTrailingZeros();
        if (s.signum() == 0) {
            return "0";
        }
        return (s.scale() < 0 ? s.setScale(0) : s).toPlainString();
    }
}
