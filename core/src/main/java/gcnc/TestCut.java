package gcnc;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Messages;
import gcnc.diag.Span;
import gcnc.dmc.Instruction;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.machine.ToolWear;
import gcnc.machine.Units;
import gcnc.machine.WearReader;
import gcnc.output.WearLines;
import gcnc.tables.Decimal;
import java.io.IOException;
import java.io.Reader;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalInt;

/**
 * The test cut, a lathe's daily loop: cut, measure, adjust the tool's wear offset, run again
 * ({@code gcnc offsets wear T01 --measured X25.37 --programmed X25.40 PART.nc}; the studio's form
 * calls the same). The change is programmed minus measured, on the axis measured and in the
 * program's terms (X as the program writes it, a diameter on a diameter machine): an OD measured
 * 0.03 small needs the tool 0.03 outward, +0.03; a bore measured 0.03 small needs the tool 0.03
 * outward too, the same +0.03, because a positive X wear moves the tool away from the centreline
 * whichever side of the stock it cuts (docs/semantics.md, "Wear offsets"). The change is held to
 * the profile's limits ({@code wear.max_step}, {@code wear.max_total}), the program is checked,
 * translated and simulated again with the new wear, which is refused when the program gets an
 * error with it; then the {@code wear.N} line is saved ({@link WearLines}).
 */
public final class TestCut {
    private TestCut() {
    }

    /** The axis a measurement is on. */
    public enum Axis {
        X, Z
    }

    /**
     * One measurement of the test cut, as the program writes coordinates (its units; X a diameter
     * on a diameter machine).
     */
    public record Measurement(Axis axis, double measured, double programmed, String measuredText,
                              String programmedText) {
        /** What the wear must change by: programmed minus measured. */
        public double change() {
            return programmed - measured;
        }

        /**
         * {@code --measured X25.37 --programmed X25.40}: an axis letter and a number each, on the
         * same axis; empty otherwise.
         */
        public static Optional<Measurement> parse(String measured, String programmed) {
            if (measured == null || programmed == null || measured.length() < 2 || programmed.length() < 2) {
                return Optional.empty();
            }
            char a = Character.toUpperCase(measured.charAt(0));
            if (a != Character.toUpperCase(programmed.charAt(0)) || (a != 'X' && a != 'Z')) {
                return Optional.empty();
            }
            OptionalDouble m = Decimal.parse(measured.substring(1));
            OptionalDouble p = Decimal.parse(programmed.substring(1));
            if (m.isEmpty() || p.isEmpty() || Math.abs(m.getAsDouble()) > 1e6 || Math.abs(p.getAsDouble()) > 1e6) {
                return Optional.empty();
            }
            return Optional.of(new Measurement(a == 'X' ? Axis.X : Axis.Z, m.getAsDouble(), p.getAsDouble(),
                    a + measured.substring(1), a + programmed.substring(1)));
        }
    }

    /**
     * The tool offset a name gives: {@code T01} or {@code 1} offset 1; {@code T0101} or {@code T0301}
     * the second pair (the offset of a four-digit T, as the checker reads it); empty when none.
     */
    public static OptionalInt offset(String name) {
        String digits = name.startsWith("T") || name.startsWith("t") ? name.substring(1) : name;
        if (!digits.matches("[0-9]{1,4}")) {
            return OptionalInt.empty();
        }
        int n = Integer.parseInt(digits);
        int offset = digits.length() <= 2 ? n : n % 100;
        return offset >= 1 && offset <= 99 ? OptionalInt.of(offset) : OptionalInt.empty();
    }

    /** One axis's wear before and after, in the offsets unit. */
    public record Change(Measurement measurement, double before, double step, double after) {
    }

    /**
     * A test cut saved.
     *
     * @param offset   the tool offset
     * @param changes  each axis changed
     * @param wear     the whole wear table now in force
     * @param file     where it was saved
     * @param verified the program checked, translated and simulated with the new wear
     * @param units    the program's units (those of the measurements)
     */
    public record Saved(int offset, List<Change> changes, ToolWear wear, Path file, Compiler.Result verified,
                        Units units) {
    }

    /** A test cut refused: the diagnostic, at the file it concerns; nothing was saved. */
    public static final class Refused extends Exception {
        private final String path;
        private final transient Diagnostic diagnostic;

        Refused(String path, Code code, Span at, Object... args) {
            super(code.id());
            this.path = path;
            this.diagnostic = Diagnostic.error(code, at, args);
        }

        public String path() {
            return path;
        }

        public Diagnostic diagnostic() {
            return diagnostic;
        }
    }

    /**
     * Where the wear of {@code session}'s machine is kept: the offsets file ({@code --offsets}, else
     * the profile's {@code offsets.file}), else the profile's own file when it is one the user gave
     * ({@code --machine FILE}); E876 for a profile gcnc ships with no offsets file.
     */
    public static Path target(Session session) throws Refused {
        MachineProfile p = session.profile();
        Optional<Path> file = WearReader.file(p.file(), session.options().offsets());
        if (file.isPresent()) {
            return file.get();
        }
        if (ProfileLoader.isPath(session.options().machine())) {
            return Path.of(session.options().machine());
        }
        throw new Refused(session.options().machine(), Code.E876_WEAR_NOWHERE_TO_SAVE, Span.of(1, 1), p.name());
    }

    /**
     * The test cut on {@code program} for tool offset {@code n}: checks the change, re-verifies the
     * program with it, saves it into {@link #target}. {@code messages} renders a new finding in the
     * refusal; {@code sim} is how the program is simulated (its blank), both times.
     */
    public static Saved cut(Session session, Path program, gcnc.sim.SimOptions sim, int n,
                            List<Measurement> measurements, Messages messages) throws Refused, IOException {
        Path target = target(session);
        MachineProfile profile = session.profile();
        String name = program.toString();
        if (profile.toolOffset(n).isEmpty()) {
            throw new Refused(name, Code.E452_WEAR_NO_TOOL_OFFSET, Span.of(1, 1), "T" + two(n), profile.name(), n);
        }
        List<Instruction> before = new ArrayList<>();
        Compiler.Result was = compile(session, program, sim, before);
        if (was.diagnostics().hasErrors()) {
            Diagnostic first = firstError(was);
            throw new Refused(name, Code.E875_WEAR_PROGRAM_NOT_CLEAN, first.span(), was.diagnostics().errorCount(),
                    first.code().id(), first.span().line());
        }
        Units units = was.simulation().map(s -> s.program()).filter(e -> e != null).map(e -> e.units())
                .orElse(profile.units());
        ToolWear wear = profile.wear();
        Optional<ToolWear.Wear> current = wear.of(n);
        double x = current.map(ToolWear.Wear::x).orElse(0.0);
        double z = current.map(ToolWear.Wear::z).orElse(0.0);
        List<Change> changes = new ArrayList<>();
        for (Measurement m : measurements) {
            double step = inOffsetsUnit(m, units, profile);
            double was0 = m.axis() == Axis.X ? x : z;
            double after = round(was0 + step);
            String axis = m.axis().name();
            if (Math.abs(step) > wear.maxStep() + 1e-9) {
                throw new Refused(target.toString(), Code.E872_WEAR_STEP, wearLine(target, current), n, axis,
                        signed(step), wear.unit(), m.programmedText(), m.measuredText(), ProfileFile.written(wear.maxStep()));
            }
            if (Math.abs(after) > wear.maxTotal() + 1e-9) {
                throw new Refused(target.toString(), Code.E873_WEAR_TOTAL, wearLine(target, current), n, axis,
                        signed(after), wear.unit(), ProfileFile.written(wear.maxTotal()));
            }
            if (m.axis() == Axis.X) {
                x = after;
            } else {
                z = after;
            }
            changes.add(new Change(m, was0, step, after));
        }
        ToolWear next = wear.with(n, x, z, target.toString(), current.map(ToolWear.Wear::line).orElse(0));
        List<Instruction> after = new ArrayList<>();
        Compiler.Result now = compile(session.withProfile(profile.withWear(next)), program, sim, after);
        if (now.diagnostics().hasErrors()) {
            Diagnostic first = firstError(now);
            throw new Refused(name, Code.E874_WEAR_NEW_FINDING, first.span(), n, describe(next, n, profile),
                    first.code().id(), first.span().line(), messages.render(first.code(), first.args()));
        }
        if (after.equals(before)) {
            throw new Refused(name, Code.E877_WEAR_OFFSET_UNUSED, Span.of(1, 1), n);
        }
        WearLines.save(target, n, ProfileFile.written(x) + ", " + ProfileFile.written(z));
        return new Saved(n, changes, next, target, now, units);
    }

    /** A wear as the pre-flight and the test cut show it ({@link ToolWear#describe}). */
    public static String describe(ToolWear wear, int n, MachineProfile p) {
        return wear.describe(n, p.diameterX());
    }

    /** The change in the offsets unit: mm (inch programs times 25.4), or counts on that axis. */
    private static double inOffsetsUnit(Measurement m, Units units, MachineProfile p) {
        double mm = m.change() * (units == Units.INCH ? 25.4 : 1);
        if (p.wear().counts()) {
            mm *= m.axis() == Axis.X ? p.x().countsPerMm() : p.z().countsPerMm();
        }
        return round(mm);
    }

    /** To 6 decimals, the finest a wear line keeps (0.0001 in is 0.00254 mm). */
    private static double round(double v) {
        return BigDecimal.valueOf(v).setScale(6, RoundingMode.HALF_EVEN).doubleValue();
    }

    /** "+0.030", "-0.0762", "0.000" ({@link ToolWear#signed}). */
    public static String signed(double v) {
        return ToolWear.signed(v);
    }

    private static String two(int n) {
        return n < 10 ? "0" + n : Integer.toString(n);
    }

    private static Span wearLine(Path target, Optional<ToolWear.Wear> current) {
        return Span.of(current.filter(w -> w.file().equals(target.toString())).map(ToolWear.Wear::line).orElse(1), 1);
    }

    private static Diagnostic firstError(Compiler.Result r) {
        return r.diagnostics().sorted().stream().filter(d -> d.severity() == gcnc.diag.Severity.ERROR).findFirst()
                .orElseThrow();
    }

    /** Check, translate and simulate as {@code gcnc compile} does, the DMC kept in {@code dmc}. */
    private static Compiler.Result compile(Session s, Path program, gcnc.sim.SimOptions sim, List<Instruction> dmc)
            throws IOException {
        Path folder = program.toAbsolutePath().getParent();
        try (Reader in = Session.decode(Files.newInputStream(program))) {
            return s.withPrograms(Optional.ofNullable(folder)).compile(in, Optional.of(sim), false, dmc::add);
        }
    }
}
