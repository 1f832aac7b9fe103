package gcnc.cli;

import gcnc.TestCut;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Phrase;
import gcnc.diag.Span;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import gcnc.sim.SimOptions;
import gcnc.tables.TableException;
import java.io.IOException;
import java.io.PrintWriter;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code gcnc offsets wear T01 --measured X25.37 --programmed X25.40 PART.nc}: the test cut
 * ({@link TestCut}): the wear change from what was measured, the program re-verified with it, the
 * {@code wear.N} line saved (docs/command-line.md, "gcnc offsets wear").
 */
@Command(name = "offsets", mixinStandardHelpOptions = true, subcommands = OffsetsCommand.Wear.class,
        description = "The tools' offsets: gcnc offsets wear adjusts a tool's wear from a measured test cut.")
final class OffsetsCommand extends StreamsCommand {
    @Override
    Integer call(PrintWriter out, PrintWriter err) {
        spec.commandLine().usage(out);
        return ExitCode.USAGE;
    }

    @Command(name = "wear", mixinStandardHelpOptions = true,
            description = {"Adjust a tool offset's wear from a test cut: the change is programmed minus measured (X as"
                    + " the program writes it, a diameter on a diameter machine; the same for an OD and a bore), held to"
                    + " wear.max_step and wear.max_total; the program is re-verified with it and the wear.N line saved"
                    + " (in --offsets FILE, the profile's offsets.file, or the --machine FILE itself)."},
            exitCodeListHeading = "%nExit status:%n",
            exitCodeList = {"0:the wear was saved", "1:refused (a limit, a new error with the new wear, the program"
                    + " unclean before, the offset not used): nothing was saved",
                    "2:usage, unreadable program, unwritable offsets file, broken table or profile"})
    static final class Wear extends StreamsCommand {
        @Mixin
        CommonOptions common;

        @Mixin
        StockOptions stock;

        @Parameters(index = "0", paramLabel = "OFFSET", description = "The tool offset: T01, T0101 (the second pair) or 1.")
        String offset;

        @Parameters(index = "1", paramLabel = "FILE", description = "The program the test cut was made with.")
        Path file;

        @Option(names = "--measured", paramLabel = "X|Z VALUE", required = true,
                description = "What was measured, as the program writes it: X25.37 (a diameter) or Z-20.05; repeatable"
                        + " (one per axis), in the order of --programmed.")
        List<String> measured = new ArrayList<>();

        @Option(names = "--programmed", paramLabel = "X|Z VALUE", required = true,
                description = "What the program cuts there: X25.40 or Z-20.")
        List<String> programmed = new ArrayList<>();

        @Option(names = {"-q", "--quiet"}, description = "Print findings and refusals only.")
        boolean quiet;

        @Override
        Integer call(PrintWriter out, PrintWriter err) {
            Reporter reporter = new Reporter(Reporter.Format.GNU, quiet, out, err, common.language());
            return RunCommand.loaded(reporter, out, err, common, true, setup -> run(setup, reporter));
        }

        private int run(CommonOptions.Setup setup, Reporter reporter) throws TableException {
            String name = SourceFiles.display(file);
            OptionalInt n = TestCut.offset(offset);
            if (n.isEmpty()) {
                reporter.report(name, Diagnostic.error(Code.E870_WEAR_OFFSET_NAME, Span.of(1, 1), offset));
                return ExitCode.PROGRAM_ERRORS;
            }
            List<TestCut.Measurement> ms = new ArrayList<>();
            if (measured.size() != programmed.size()) {
                reporter.report(name, Diagnostic.error(Code.E871_WEAR_MEASUREMENT, Span.of(1, 1),
                        String.join(" ", measured), String.join(" ", programmed)));
                return ExitCode.PROGRAM_ERRORS;
            }
            for (int i = 0; i < measured.size(); i++) {
                Optional<TestCut.Measurement> m = TestCut.Measurement.parse(measured.get(i), programmed.get(i));
                if (m.isEmpty() || ms.stream().anyMatch(o -> o.axis() == m.get().axis())) {
                    reporter.report(name, Diagnostic.error(Code.E871_WEAR_MEASUREMENT, Span.of(1, 1), measured.get(i),
                            programmed.get(i)));
                    return ExitCode.PROGRAM_ERRORS;
                }
                ms.add(m.get());
            }
            SimOptions sim = stock.options(setup.profile(), file, reporter.phrases(), spec, reporter::say);
            TestCut.Saved saved;
            try {
                saved = TestCut.cut(setup.session(), file, sim, n.getAsInt(), ms, reporter.messages());
            } catch (TestCut.Refused r) {
                reporter.report(r.path(), r.diagnostic());
                return ExitCode.PROGRAM_ERRORS;
            } catch (IOException e) {
                return reporter.ioFault(name, Phrase.IO_CANNOT_WRITE, e);
            }
            MachineProfile p = setup.profile();
            Phrases say = reporter.phrases();
            for (TestCut.Change c : saved.changes()) {
                String key = c.measurement().axis() == TestCut.Axis.Z ? "offsets.change.z"
                        : p.diameterX() ? "offsets.change.diameter" : "offsets.change.radius";
                reporter.say(say.get(key, "T" + two(saved.offset()), TestCut.signed(c.before()),
                        TestCut.signed(c.after()), TestCut.signed(c.step()), c.measurement().programmedText(),
                        c.measurement().measuredText(), saved.wear().unit(),
                        inProgramUnits(c, saved.units(), saved.wear().counts())));
            }
            reporter.report(name, saved.verified().diagnostics());
            reporter.say(say.get("offsets.verified", name, TestCut.describe(saved.wear(), saved.offset(), p),
                    saved.verified().diagnostics().errorCount() == 0 ? say.get("no_errors")
                            : say.count(saved.verified().diagnostics().errorCount(), "error"),
                    say.count(saved.verified().diagnostics().size() - saved.verified().diagnostics().errorCount(),
                            "finding")));
            reporter.say(say.get("offsets.saved", saved.offset(), saved.file()));
            return ExitCode.CLEAN;
        }

        /** For an inch program, the change in inches too ("; +0.0030 in"); else nothing. */
        private static String inProgramUnits(TestCut.Change c, Units units, boolean counts) {
            if (units != Units.INCH || counts) {
                return "";
            }
            BigDecimal in = BigDecimal.valueOf(c.step()).divide(new BigDecimal("25.4"), 5, RoundingMode.HALF_EVEN)
                    .stripTrailingZeros();
            if (in.scale() < 4) {
                in = in.setScale(4);
            }
            return "; " + (in.signum() > 0 ? "+" : "") + in.toPlainString() + " in";
        }

        private static String two(int n) {
            return n < 10 ? "0" + n : Integer.toString(n);
        }
    }
}
