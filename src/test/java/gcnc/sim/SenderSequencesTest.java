package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.machine.MachineProfile;
import gcnc.machine.Plane;
import gcnc.send.CompiledRun;
import gcnc.send.DmcProgram;
import gcnc.send.MapReader;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The sender's sequences of a program (gcnc.send.DmcProgram: what its resume, progress and way back rest
 * on) are the motions the simulator's controller ran, one for one (issue 32, item 2): as many, each
 * spanning the lines from its first command to the wait for it, each segment where the controller put
 * it, a thread pass ending where the controller's geared pass ends; from a compile and from the DMC read back.
 */
class SenderSequencesTest {
    /** One motion the controller handed on: its segments (machine counts) and speed. */
    record Ran(List<Segment> segments, double speed) {
    }

    @Test
    void theSendersSequencesAreTheMotionsTheControllerRan() throws Exception {
        List<Path> programs = new ArrayList<>();
        for (String dir : List.of("src/test/resources/cycles", "src/test/resources/chamfer")) {
            try (Stream<Path> s = Files.list(Path.of(dir))) {
                s.filter(p -> p.toString().endsWith(".nc")).sorted().forEach(programs::add);
            }
        }
        int sequences = 0;
        int threads = 0;
        int arcs = 0;
        for (Path f : programs) {
            String name = f.getFileName().toString();
            String machine = name.substring(name.indexOf('.') + 1, name.lastIndexOf('.'));
            Session session = Session.open(Session.Options.defaults().withMachine(machine));
            CompiledRun seen = new CompiledRun();
            String text = Files.readString(f);
            session.compile(new StringReader(text), Optional.of(session.simulation()), false, line -> { }, seen);
            DmcProgram program = seen.program(session.profile());
            List<Ran> ran = replay(program, session.profile());
            same(name, program, ran, session.profile());
            List<String> lines = new ArrayList<>();
            program.instructions().forEach(i -> lines.add(i.text()));
            DmcProgram back = DmcProgram.read(lines, new MapReader.Map(new long[0], new int[0], new String[0]),
                    session.profile());
            same(name + " read back", back, ran, session.profile());
            sequences += program.sequences().size();
            for (Sequence s : program.sequences()) {
                threads += s.isThreadPass() ? 1 : 0;
                arcs += s.pieces().stream().filter(p -> p instanceof Sequence.Arc).count();
            }
        }
        // the samples hold vector sequences, arcs and thread passes
        assertTrue(sequences > 100 && threads > 5 && arcs > 5, sequences + " " + threads + " " + arcs);
    }

    /** The program's lines through the controller by itself, recording each motion it starts. */
    static List<Ran> replay(DmcProgram program, MachineProfile profile) {
        List<Ran> ran = new ArrayList<>();
        ReplayListener record = new ReplayListener() {
            @Override
            public void sequence(List<Segment> segments, double speed, gcnc.dmc.Source at) {
                ran.add(new Ran(List.copyOf(segments), speed));
            }

            @Override
            public void dwell(double seconds, int line) {
            }

            @Override
            public void tool(int n, gcnc.dmc.Source at) {
            }

            @Override
            public void output(int bit, boolean on, int line) {
            }

            @Override
            public void spindleVolts(double volts, int line) {
            }

            @Override
            public void report(Code code, gcnc.dmc.Source at, Object... args) {
            }
        };
        Plane plane = Plane.of(profile);
        ThreadGearing gearing = new ThreadGearing(plane, profile.encoder().map(e -> Plane.channel(e.channel())).orElse(-1),
                profile.encoder().map(e -> e.countsPerRev()).orElse(0), profile.rpmPerVolt(),
                Simulator.threadTolerance(profile, SimOptions.defaults()), record);
        int analog = gcnc.machine.MachineIo.of(profile).drive()
                instanceof gcnc.machine.MachineIo.SpindleDrive.Analog a ? a.output() : -1;
        ReplayController dmc = new ReplayController(plane, profile.home().x(), profile.home().z(), profile.acceleration(),
                profile.deceleration(), profile.rapidSpeed(), profile.spindleAxis(), analog, gearing, record,
                new SequenceLog());
        program.instructions().forEach(dmc::run);
        dmc.startBegun();
        return ran;
    }

    static void same(String name, DmcProgram program, List<Ran> ran, MachineProfile profile) {
        Plane plane = Plane.of(profile);
        List<Sequence> sequences = program.sequences();
        assertEquals(ran.size(), sequences.size(), name + ": sequences");
        for (int k = 0; k < ran.size(); k++) {
            Sequence s = sequences.get(k);
            Ran r = ran.get(k);
            String at = name + " sequence " + k + " (lines " + s.first() + ".." + s.last() + ")";
            Command wait = program.command(s.last());
            assertTrue(wait instanceof Command.AwaitSequence || wait instanceof Command.AfterMotion, at + ": ends on " + wait);
            assertTrue(k == 0 || sequences.get(k - 1).last() < s.first(), at + ": overlaps the one before");
            Segment first = r.segments().get(0);
            Segment last = r.segments().get(r.segments().size() - 1);
            point(at + " start", plane, s.start(), first.fromX(), first.fromZ());
            point(at + " end", plane, s.end(), last.toX(), last.toZ());
            if (s.isThreadPass()) {
                assertEquals(0, s.speed(), at);
                continue;
            }
            assertEquals(r.speed(), s.speed(), at + ": speed");
            assertEquals(r.segments().size(), s.pieces().size(), at + ": pieces");
            for (int i = 0; i < r.segments().size(); i++) {
                Segment g = r.segments().get(i);
                Sequence.Piece p = s.pieces().get(i);
                assertTrue(p.line() >= s.first() && p.line() <= s.last(), at + " piece " + i + " outside its lines");
                assertEquals(g.instruction().command(), program.command(p.line()), at + " piece " + i + ": its line");
                assertEquals(g.arc(), p instanceof Sequence.Arc, at + " piece " + i);
                point(at + " piece " + i + " from", plane, p.from(), g.fromX(), g.fromZ());
                point(at + " piece " + i + " to", plane, p.to(), g.toX(), g.toZ());
                assertEquals(g.length(), p.length(), 1e-6, at + " piece " + i + ": length");
            }
        }
    }

    /** A point of the Galil plane is the controller's point in machine counts. */
    static void point(String what, Plane plane, double[] galil, double x, double z) {
        assertEquals(x, plane.machineX(galil[0], galil[1]), 1e-9, what + " X");
        assertEquals(z, plane.machineZ(galil[0], galil[1]), 1e-9, what + " Z");
    }
}
