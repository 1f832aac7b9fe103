package gcnc.sim;

import gcnc.DmcCorpus;
import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.DmcReader;
import gcnc.dmc.Instruction;
import gcnc.dmc.Source;
import gcnc.machine.Plane;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The shared DMC corpus ({@link DmcCorpus}) on the simulator's controller, the reading of Galil that
 * gcnc's own proof of a program rests on: each program read as the simulator reads a .dmc file and run
 * through the controller's limits ({@link gcnc.galil.LimitCheck}, the DMC-4040's, the virtual controller's model)
 * and {@link ReplayController}, as {@code gcnc simulate FILE.dmc} runs it, on the plane XY (X the first channel, both signs +1, so that a
 * machine count is a Galil count) with the spindle on channel C (a 4,096-count encoder, 410 r/min a
 * volt, the virtual controller's spindle).
 */
class DmcCorpusSimTest {
    static List<DmcCorpus.Case> cases() {
        return DmcCorpus.cases();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void theSimulatorsControllerRunsTheCorpus(DmcCorpus.Case c) {
        DmcCorpus.assertRan(c, "the simulator", run(c.program()));
    }

    static List<String> run(String program) {
        List<String> ran = new ArrayList<>();
        // the lines holding a BG of the plane's axes, as a thread pass's settling move is started (each
        // noted before its BG runs, which is when the controller hands the pass on)
        java.util.Set<Integer> passes = new java.util.HashSet<>();
        Plane plane = new Plane("XY", true, 1, 1);
        long[] lastTrip = {-1};
        ReplayListener record = new ReplayListener() {
            @Override
            public void sequence(List<Segment> segments, double speed, Source at) {
                if (passes.contains(at.line())) {
                    // a thread pass (started by the BG of its settling move): the trace has where it settled
                    Segment s = segments.get(segments.size() - 1);
                    ran.add("PA " + Math.round(plane.galil1(s.toX(), s.toZ())) + " "
                            + Math.round(plane.galil2(s.toX(), s.toZ())));
                    return;
                }
                for (Segment s : segments) {
                    ran.add((s.arc() ? "CR " : "VP ") + Math.round(plane.galil1(s.toX(), s.toZ())) + " "
                            + Math.round(plane.galil2(s.toX(), s.toZ())));
                }
            }

            @Override
            public void onTheWay(Source what, List<Source> around, long trip, String text) {
                if (trip != lastTrip[0]) {
                    ran.add("AV " + trip);
                    lastTrip[0] = trip;
                }
            }

            @Override
            public void dwell(double seconds, int line) {
            }

            @Override
            public void tool(int n, Source at) {
            }

            @Override
            public void output(int bit, boolean on, int line) {
                ran.add((on ? "SB " : "CB ") + bit);
            }

            @Override
            public void spindleVolts(double volts, int line) {
            }

            @Override
            public void report(Code code, Source at, Object... args) {
                ran.add("! " + at.line());
            }
        };
        ThreadGearing gearing = new ThreadGearing(plane, Plane.channel('C'), 4096, 410, 2, record);
        ReplayController dmc = new ReplayController(plane, 0, 0, 1024000, 1024000, 20000, 'C', -1, gearing, record,
                new SequenceLog());
        gcnc.diag.Diagnostics refused = new gcnc.diag.Diagnostics();
        gcnc.galil.LimitCheck limits = new gcnc.galil.LimitCheck(new gcnc.machine.ControllerLimits(
                gcnc.machine.GalilModels.builtIn().find(gcnc.machine.GalilModels.DEFAULT).orElseThrow()), refused, i -> {
                    // the controller does not run a refused command, nor (without #CMDERR) any after it; the
                    // simulator's own replay goes on, to report every error of a file
                    if (refused.sorted().isEmpty()) {
                        dmc.run(i);
                    }
                });
        List<String> lines = program.lines().toList();
        for (int k = 0; k < lines.size(); k++) {
            int line = k + 1;
            for (String statement : DmcReader.statements(lines.get(k))) {
                Command cmd = DmcReader.read(statement, (code, args) -> refused.error(code, gcnc.diag.Span.of(line, 1), args));
                if (cmd instanceof Command.Begin) {
                    passes.add(line);
                }
                if (cmd != null) {
                    limits.accept(new Instruction(cmd, Source.line(line)));
                }
            }
        }
        dmc.startBegun();
        refused.sorted().forEach(d -> ran.add("! " + d.span().line()));
        return ran;
    }
}
