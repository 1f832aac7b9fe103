package gcnc.junit;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.diag.Diagnostic;
import gcnc.diag.GnuRenderer;
import gcnc.sim.ProgramEnvelope;
import gcnc.sim.SimReport;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Fluent assertions on a part program that read like the shop's intent:
 *
 * <pre>
 * assertThat(program("programs/flange.nc")).on(machine("haas"))
 *         .compilesClean()
 *         .staysWithin(0, Double.POSITIVE_INFINITY, -30, Double.POSITIVE_INFINITY) // X as written, Z from work zero: never behind Z-30
 *         .cycleTimeBelow(Duration.ofMinutes(3));
 * </pre>
 *
 * The program is compiled and simulated once, on the first assertion, exactly as {@code gcnc
 * compile} does with the same inputs ({@link Session}); every failure lists the findings GCC-style.
 */
public final class ProgramAssert {
    private final Path program;
    private final Session session;
    private Compiler.Result result;

    private ProgramAssert(Path program, Session session) {
        this.program = program;
        this.session = session;
    }

    /** A part program file. */
    public static Path program(String path) {
        return Path.of(path);
    }

    /** A shipped machine profile (or a .machine file) with the built-in tables. */
    public static Session machine(String nameOrPath) {
        return GcodeAssertions.session(nameOrPath);
    }

    /** Assertions on {@code program}, on the default machine until {@link #on} says which. */
    public static ProgramAssert assertThat(Path program) {
        return new ProgramAssert(program, null);
    }

    /** The same program on this machine (and tables, control, blank: all the session holds). */
    public ProgramAssert on(Session machine) {
        return new ProgramAssert(program, machine);
    }

    /**
     * No error (warnings and notes, like the command line's exit status 0, do not fail it; nor does
     * a finding the program's waivers accept, which it names on standard output).
     */
    public ProgramAssert compilesClean() {
        if (result().diagnostics().hasErrors()) {
            throw new AssertionError(program + " is not clean on " + session().profile().name() + ":\n" + findings());
        }
        if (!said && result().diagnostics().waivedCount() > 0) {
            said = true;
            GcodeAssertions.sayWaived(program, session(), List.of(findings().split("\n")));
        }
        return this;
    }

    /** Whether the waived findings were named already (once per program, however many assertions). */
    private boolean said;

    /** Exactly these diagnostic codes, in order ("E305", "E113", ...). */
    public ProgramAssert hasFindings(String... codes) {
        List<String> actual = new ArrayList<>();
        for (Diagnostic d : result().diagnostics().sorted()) {
            actual.add(d.code().id());
        }
        if (!actual.equals(List.of(codes))) {
            throw new AssertionError(program + ": expected " + List.of(codes) + " but got:\n" + findings());
        }
        return this;
    }

    /**
     * The tool tip stays within these limits as the program writes coordinates: X as the program
     * writes it (a diameter where the machine's control reads X as one), Z from work zero, in the
     * program's units (what the simulation summary prints first as its envelope). Each move is
     * measured in its own block's frame (work and tool offsets), so a G28 to the reference point
     * counts where the control's position display would put it; an infinite limit is open:
     * {@code staysWithin(-2, Double.POSITIVE_INFINITY, -30, Double.POSITIVE_INFINITY)} is "never
     * behind Z-30". {@link #staysWithinMachine} asks the same in the machine frame.
     */
    public ProgramAssert staysWithin(double xMin, double xMax, double zMin, double zMax) {
        SimReport r = simulation();
        ProgramEnvelope p = r.program();
        if (p == null) {
            throw new AssertionError(program + " did not move: nothing to keep within X " + xMin + ".." + xMax
                    + ", Z " + zMin + ".." + zMax);
        }
        if (!p.within(xMin, xMax, zMin, zMax)) {
            throw new AssertionError(String.format(Locale.ROOT, "%s moves over X %s..%s (%s), Z %s..%s %s from work"
                    + " zero, not within X %s..%s, Z %s..%s (machine frame: X %.3f..%.3f mm, a radius; Z %.3f..%.3f mm)",
                    program, programmed(p.xMin(), p), programmed(p.xMax(), p), p.xMode(), programmed(p.zMin(), p),
                    programmed(p.zMax(), p), p.unit(), limit(xMin), limit(xMax), limit(zMin), limit(zMax),
                    r.xMinMm(), r.xMaxMm(), r.zMinMm(), r.zMaxMm()));
        }
        return this;
    }

    /**
     * The tool tip stays within these limits in the machine frame, in mm: X as a radius from
     * machine X zero, Z along the bed (the simulation summary's second envelope): what
     * {@code staysWithin} asked in earlier builds.
     */
    public ProgramAssert staysWithinMachine(double xMinMm, double xMaxMm, double zMinMm, double zMaxMm) {
        SimReport r = simulation();
        if (r.xMinMm() < xMinMm || r.xMaxMm() > xMaxMm || r.zMinMm() < zMinMm || r.zMaxMm() > zMaxMm) {
            throw new AssertionError(String.format(Locale.ROOT, "%s moves over machine X %.3f..%.3f mm (radius),"
                    + " Z %.3f..%.3f mm, not within X %s..%s, Z %s..%s", program, r.xMinMm(), r.xMaxMm(), r.zMinMm(),
                    r.zMaxMm(), limit(xMinMm), limit(xMaxMm), limit(zMinMm), limit(zMaxMm)));
        }
        return this;
    }

    /** A program coordinate with its units' decimals (3 for mm, 4 for inches). */
    private static String programmed(double v, ProgramEnvelope p) {
        return String.format(Locale.ROOT, p.units() == gcnc.machine.Units.INCH ? "%.4f" : "%.3f", v);
    }

    /** A limit as the test wrote it: 30, -2.5, open (an infinity). */
    private static String limit(double v) {
        if (Double.isInfinite(v)) {
            return v > 0 ? "+inf" : "-inf";
        }
        return java.math.BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
    }

    /** The simulated cycle time (the moves' trapezoidal profiles and the dwells) is below {@code limit}. */
    public ProgramAssert cycleTimeBelow(Duration limit) {
        double seconds = simulation().cycleSeconds();
        if (seconds >= limit.toMillis() / 1000.0) {
            throw new AssertionError(String.format(Locale.ROOT, "%s takes about %.1f s, not below %s",
                    program, seconds, limit));
        }
        return this;
    }

    private SimReport simulation() {
        compilesClean();
        return result().simulation().orElseThrow(() -> new AssertionError(program + " was not simulated"));
    }

    private Session session() {
        return session != null ? session : GcodeAssertions.session(gcnc.machine.ProfileLoader.DEFAULT);
    }

    private Compiler.Result result() {
        if (result == null) {
            try {
                result = session().compile(program);
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read " + program, e);
            }
        }
        return result;
    }

    private String findings() {
        GnuRenderer g = new GnuRenderer(session().tables().messages().in(ErrorMessages.Lang.EN));
        List<String> out = new ArrayList<>();
        for (Diagnostic d : result().diagnostics().sorted()) {
            out.add(g.render(program.toString(), d));
        }
        return String.join("\n", out);
    }
}
