package gcnc.galil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import gcnc.machine.ProfileLoader;
import gcnc.sim.SimOptions;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Arcs blended one into the next: each CR starts where the one before really ended, a fraction of
 * a count off the whole count it was planned from. Left alone the fractions add up along the
 * chain, and the sequence ends a count off its target: the next sequence starts there, and a G28
 * and G29 after it land a count and a half off (E308, found by PipelineFuzzTest's long campaign,
 * seeds 248 and 1087). The galil dialect closes an arc whose end would round to another count
 * than its target's with a VP to the target, as it does for the planner's own closing arcs.
 */
class ArcChainTest {
    private static final Tables TABLES = Tables.builtIn();

    private static Compiler.Result compile(String program, String machine, List<Instruction> out) throws Exception {
        return Compiler.compile(new StringReader(program), new Compiler.Settings(TABLES,
                ProfileLoader.load(machine, TableSource.builtIn(), TABLES), Dialect.Kind.GALIL, Optional.of(SimOptions.defaults().withoutBlank())),
                out::add);
    }

    @Test
    void twoArcsAndAReturnThroughTheReferencePointEndOnTheirCounts() throws Exception {
        String program = String.join("\n", "G21 G90 G98", "G50 S2500", "M11", "T0101", "S1000 M03", "G00 X60. Z5.",
                "G01 F100.",
                "G03 X50.251143 Z11.043686 I-9.42 K-2.61", // line 8: 313 degrees, r 9.775
                "G02 X81.648697 Z24.269667 I8.29 K6.09",   // line 9: 188 degrees, started where line 8 really ended
                "G28 U0. W0.", "G29 U0. W0.", "M30") + "\n";
        List<Instruction> out = new ArrayList<>();
        Compiler.Result r = compile(program, "generic", out);
        assertTrue(r.ok(), r.diagnostics().sorted().toString()); // was E308 at line 11: 1.504 counts off
        // the second arc is closed by a VP in its own sequence: line 9's instructions are CR, VP
        List<String> line9 = new ArrayList<>();
        for (Instruction i : out) {
            if (i.source().line() == 9 && (i.command() instanceof Command.CircularArc || i.command() instanceof Command.VectorPosition)) {
                line9.add(i.command().getClass().getSimpleName());
            }
        }
        assertEquals(List.of("CircularArc", "VectorPosition"), line9);
    }

    /** Random profiles of 40 arcs blended end to end, on three machines: no arc or sequence drifts off its count. */
    @Test
    void longChainsOfArcsStayOnTheirCounts() throws Exception {
        for (String machine : List.of("generic", "haas", "thesis-2004")) {
            for (int seed = 1; seed <= 12; seed++) {
                Random rnd = new Random(seed);
                StringBuilder p = new StringBuilder(machine.equals("thesis-2004") ? "G21 G90 G98\nM11\n" : "G21 G90 G98\n");
                p.append("T0101\nS1000 M03\nG00 X60. Z2.\nG01 X40. Z0. F100.\n");
                double x = 40;
                double z = 0;
                for (int i = 0; i < 40; i++) {
                    double r = 2 + rnd.nextDouble() * 12;
                    x += rnd.nextDouble() * 3 - 1.5;
                    z -= 0.5 + rnd.nextDouble() * 3;
                    p.append(String.format(Locale.ROOT, "G0%d X%.4f Z%.4f R%.4f%n", 2 + i % 2, x, z, r));
                }
                p.append("G28 U0. W0.\nG29 U0. W0.\nG01 X62.\nG00 Z2.\nM30\n");
                Compiler.Result r = compile(p.toString(), machine, new ArrayList<>());
                assertTrue(r.diagnostics().sorted().stream().noneMatch(d -> d.code().name().startsWith("E308")),
                        machine + " seed " + seed + ": " + r.diagnostics().sorted() + "\n" + p);
            }
        }
    }
}
