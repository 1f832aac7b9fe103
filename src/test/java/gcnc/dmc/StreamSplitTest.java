package gcnc.dmc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Origin;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.sim.SimOptions;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * The stream form is the program form rearranged, nothing else: the resident set-up, the stream
 * with every call of a moved block put back in place, and the resident routines give back the
 * program form's instructions in order, with their sources.
 */
class StreamSplitTest {
    private static List<Instruction> programForm(String file, String machine, gcnc.sim.StockSize stock) throws Exception {
        Tables tables = Tables.builtIn();
        MachineProfile profile = ProfileLoader.load(machine, TableSource.builtIn(), tables);
        SimOptions o = stock == null ? SimOptions.defaults() : SimOptions.defaults().withStock(stock);
        Compiler.Settings s = new Compiler.Settings(tables, profile, Dialect.Kind.GALIL, Optional.of(o));
        List<Instruction> out = new ArrayList<>();
        try (Reader in = Files.newBufferedReader(Path.of(file))) {
            Compiler.Result r = Compiler.compile(in, s, out::add);
            assertTrue(r.ok(), () -> file + ": " + r.diagnostics().sorted());
        }
        return out;
    }

    @Test
    void theStreamFormPutBackTogetherIsTheProgramForm() throws Exception {
        for (String[] c : List.of(new String[] {"src/test/resources/stream/thread-shaft.nc", "haas", "20,100,60"},
                new String[] {"docs/examples/bushing.nc", "haas", "38.1,200,150"}, new String[] {"samples/bishop.nc", "thesis-2004", null},
                new String[] {"samples/dwell-css.nc", "generic", null}, new String[] {"samples/home.nc", "generic", null},
                new String[] {"samples/turning.nc", "generic", null})) {
            double[] b = c[2] == null ? null : java.util.Arrays.stream(c[2].split(",")).mapToDouble(Double::parseDouble).toArray();
            List<Instruction> program = programForm(c[0], c[1], b == null ? null : new gcnc.sim.StockSize(b[0], b[1], b[2], 0));
            List<Instruction> stream = new ArrayList<>();
            StreamSplit split = new StreamSplit(stream::add, 2000, 80);
            program.forEach(split);
            StreamSplit.Result r = split.finish();
            assertTrue(r.held());
            assertEquals(r.residentLines(), LinePacker.count(r.resident(), 80), c[0]);
            assertEquals(stream.size(), r.streamLines(), c[0]);
            assertEquals(program, putBack(r.resident(), stream), c[0]);
        }
    }

    /** The resident's set-up (without gready), the stream with each JS #Bn replaced by the routine, then the resident from its EN without the moved routines. */
    private static List<Instruction> putBack(List<Instruction> resident, List<Instruction> stream) {
        int end = 0;
        while (!(resident.get(end).command() instanceof Command.End)) {
            end++;
        }
        Map<String, List<Instruction>> moved = new java.util.HashMap<>();
        List<Instruction> after = new ArrayList<>();
        for (int i = end + 1; i < resident.size(); i++) {
            if (resident.get(i).command() instanceof Command.Label l && l.name().matches("B[0-9]+")) {
                List<Instruction> body = new ArrayList<>();
                for (i++; !(resident.get(i).command() instanceof Command.End); i++) {
                    body.add(resident.get(i));
                }
                moved.put(l.name(), body);
            } else {
                after.add(resident.get(i));
            }
        }
        List<Instruction> out = new ArrayList<>();
        for (Instruction i : resident.subList(0, end)) {
            if (!(i.command() instanceof Command.SetVariable v && v.name().equals(StreamSplit.READY))) {
                out.add(i);
            }
        }
        for (Instruction i : stream) {
            if (i.command() instanceof Command.Call call && moved.containsKey(call.label())) {
                out.addAll(moved.get(call.label()));
            } else {
                out.add(i);
            }
        }
        out.add(resident.get(end));
        out.addAll(after);
        return out;
    }

    @Test
    void aBlockThatMustRunInsideTheControllerAndIsTooLongForARoutineIsE243() throws Exception {
        MachineProfile profile = ProfileLoader.load("haas", TableSource.builtIn(), Tables.builtIn());
        Source block = new Source(Origin.PROGRAM, 12, 0, 7);
        List<Instruction> in = new ArrayList<>();
        in.add(new Instruction(new Command.Label("GCNC"), Source.NONE));
        in.add(new Instruction(new Command.WaitPast(false, 'Z', new Command.Operand.Count(100)), block));
        for (int i = 0; i < StreamSplit.RUN_LIMIT; i++) {
            in.add(new Instruction(new Command.Output(1, i % 2 == 0), block));
        }
        in.add(new Instruction(new Command.End(), Source.NONE));
        Diagnostics d = new Diagnostics();
        FormChoice choice = new FormChoice(Optional.of(Form.STREAM), profile.controllerLimits(), i -> { }, i -> { });
        in.forEach(choice);
        assertEquals(Form.STREAM, choice.finish(d));
        assertEquals(List.of(Code.E243_BLOCK_TOO_LONG_TO_EMBED + "@12"), d.sorted().stream().map(x -> x.code() + "@" + x.span().line()).toList());
    }

    @Test
    void aResidentLongerThanTheMemoryIsE239AndTheProgramFormLongerThanItIsE238() throws Exception {
        MachineProfile profile = ProfileLoader.load("haas", TableSource.builtIn(), Tables.builtIn());
        List<Instruction> in = new ArrayList<>();
        in.add(new Instruction(new Command.Label("GCNC"), Source.NONE));
        // 2,100 thread blocks: each wait ends a packed line, so 2,102 program lines; as routines (#Bn;MF, then
        // the outputs and EN) 4,200 resident lines
        for (int b = 1; b <= 2100; b++) {
            Source s = new Source(Origin.PROGRAM, b, 0, b);
            in.add(new Instruction(new Command.WaitPast(false, 'Z', new Command.Operand.Count(b)), s));
            for (int k = 0; k < 5; k++) {
                in.add(new Instruction(new Command.Output(1, true), s));
            }
        }
        in.add(new Instruction(new Command.End(), Source.NONE));
        Diagnostics stream = new Diagnostics();
        FormChoice s = new FormChoice(Optional.empty(), profile.controllerLimits(), i -> { }, i -> { });
        in.forEach(s);
        assertEquals(Form.STREAM, s.finish(stream));
        assertEquals(List.of(Code.E239_RESIDENT_DOES_NOT_FIT), stream.sorted().stream().map(x -> x.code()).toList());
        Diagnostics program = new Diagnostics();
        FormChoice p = new FormChoice(Optional.of(Form.PROGRAM), profile.controllerLimits(), i -> { }, i -> { });
        in.forEach(p);
        assertEquals(Form.PROGRAM, p.finish(program));
        assertEquals(List.of(Code.E238_PROGRAM_DOES_NOT_FIT), program.sorted().stream().map(x -> x.code()).toList());
    }

    @Test
    void aResidentProgramLongerThanAReplayReadsIsE244() {
        StringBuilder resident = new StringBuilder("#GCNC\n");
        for (int i = 0; i < gcnc.sim.StreamReplay.RESIDENT_LINES; i++) {
            resident.append("gline=").append(i).append('\n');
        }
        Diagnostics d = new Diagnostics();
        MachineProfile profile;
        try {
            profile = ProfileLoader.load("generic", TableSource.builtIn(), Tables.builtIn());
        } catch (Exception e) {
            throw new AssertionError(e);
        }
        gcnc.sim.StreamReplay.replay(new java.io.BufferedReader(new java.io.StringReader(resident.toString())), null,
                new java.io.BufferedReader(new java.io.StringReader("EN\n")), null, profile, SimOptions.defaults(), d);
        assertEquals(List.of(Code.E244_RESIDENT_TOO_LONG_TO_REPLAY + "@" + (gcnc.sim.StreamReplay.RESIDENT_LINES + 1)),
                d.sorted().stream().map(x -> x.code() + "@" + x.span().line()).toList());
    }
}
