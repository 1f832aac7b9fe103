package gcnc.galil;

import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.diag.Diagnostic;
import gcnc.dmc.Instruction;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * Issue 30, item 3: every M code of the Haas and Fanuc tables has a defined machine behaviour. Each
 * is compiled in a small turning program on its control's shipped machine; it must write Galil code
 * at its line (an output, the spindle's volts, a stop's wait), or be reported there (an error such as
 * E110 "not supported yet", the warning E113 of an output the profile lacks, a note such as E649),
 * or be one of the functions below that the control itself runs without the machine doing anything,
 * each with the reason. An M00 that compiled to nothing failed here.
 */
class MCodeBehaviourTest {
    /** Functions that drive nothing on the machine, and why that is what the control does. */
    static final Map<MRole, String> NOTHING_TO_DRIVE = Map.of(
            MRole.THREAD_CHAMFER_ON, "Haas M23: tells the next G76/G92 passes to chamfer their pull-out (docs/threading.md)",
            MRole.THREAD_CHAMFER_OFF, "Haas M24: tells the next G76/G92 passes to pull straight out (docs/threading.md)",
            MRole.OPTIONAL_STOP, "M01 with the optional stop switch off (the shipped default) runs through, as the"
                    + " control does; with it on it is M00 (RunProgramStopTest)",
            MRole.CALL, "M98: program flow, followed at compile time (docs/program-flow.md)",
            MRole.LOCAL_CALL, "Haas M97: program flow, followed at compile time (docs/program-flow.md)",
            MRole.RETURN, "M99: program flow, followed at compile time (docs/program-flow.md)",
            MRole.END, "M02/M30: the end of the program, EN after the footer");

    @Test
    void everyHaasAndFanucMCodeDoesSomethingOrSaysWhy() throws Exception {
        List<String> silent = new ArrayList<>();
        // machine, control, the feed-per-revolution and spindle-clamp words of its G code system
        for (String[] c : new String[][] {{"haas", "haas", "G99", "G50"}, {"fanuc", "fanuc-a", "G99", "G50"},
                {"fanuc", "fanuc-b", "G95", "G92"}}) {
            Session s = Session.open(Session.Options.defaults().withMachine(c[0]).withControl(c[1]));
            for (MFunction f : s.profile().control().allM()) {
                if (NOTHING_TO_DRIVE.containsKey(f.role())) {
                    continue;
                }
                // line 6 holds the M code, between a rapid and a feed, the spindle turning
                String program = String.join("\n", "G21 " + c[2], c[3] + " S2500", "T0101", "G97 S500 M03", "G00 X50. Z5.",
                        f.name(), "G01 X48. F0.2", "G00 X60. Z10.", "M05", "M30", "");
                List<Instruction> out = new ArrayList<>();
                Compiler.Result r = s.compile(new StringReader(program), Optional.empty(), false, out::add);
                boolean wrote = out.stream().anyMatch(i -> i.source().line() == 6
                        && !(i.command() instanceof gcnc.dmc.Command.SetVariable v && v.name().equals("gline")));
                boolean reported = false;
                for (Diagnostic d : r.diagnostics().sorted()) {
                    reported |= d.span().line() == 6;
                    // the program before the M code is clean (after it, an error may be its consequence: M05 then a feed)
                    assertTrue(d.span().line() >= 6 || d.severity() != gcnc.diag.Severity.ERROR, c[1] + " " + f.name()
                            + ": " + d);
                }
                if (!wrote && !reported) {
                    silent.add(c[1] + " " + f.name() + " (" + f.role().name().toLowerCase() + ")");
                }
            }
        }
        assertTrue(silent.isEmpty(), "M codes that compile to nothing and say nothing: " + silent);
    }
}
