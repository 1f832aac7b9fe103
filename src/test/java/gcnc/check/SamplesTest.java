package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class SamplesTest {
    private static String read(String name) throws IOException {
        return Files.readString(Path.of("samples", name));
    }

    @ParameterizedTest
    @ValueSource(strings = {"arcs.nc", "dwell-css.nc", "home.nc", "offsets.nc", "turning.nc", "units.nc"})
    void samplesCheckCleanUnderGeneric(String name) throws IOException {
        assertEquals("", Run.generic(read(name)).errors());
    }

    @Test
    void bishopChecksCleanAndStartsFromHomeWithTheThesisOffset() throws IOException {
        Run r = Run.thesis(read("bishop.nc"));
        assertEquals("", r.errors());
        int motions = 0;
        for (CheckedBlock b : r.blocks) {
            motions += b.motions().size();
        }
        assertEquals(57, motions, "Table 5.2 has 57 motion groups");
        Motion.Linear first = (Motion.Linear) r.line(2).motions().get(0);
        assertEquals(new Point(0, 0), first.from());
        // X+3234 x 1.5 - 20000, Z+00500 x 1.5 - 20000
        assertEquals(new Point(-15149, -19250), first.to());
    }

    @Test
    void bishopG50BlockEmitsOnlyItsMFunctionsInSourceOrder() throws IOException {
        CheckedBlock b = Run.thesis(read("bishop.nc")).line(4);
        assertEquals(List.of(new MCall(11), new MCall(3)), b.before());
        assertEquals(List.of(), b.motions());
        assertEquals(List.of(), b.after());
        assertEquals(false, b.spindleRpm().isPresent());
    }

    @Test
    void bishopArcHasItsTrueRadiusAndSignedRWord() throws IOException {
        // N240 G03 X+1000 R1400 F050 from X800 Z0: R1400 x 1.5 = 2100 counts
        Motion.Arc a = (Motion.Arc) Run.thesis(read("bishop.nc")).line(36).motions().get(0);
        assertEquals(2100, a.radius(), 1e-9);
        assertEquals(2100, a.words().r(), 1e-9);
        assertEquals(new Point(800 * 1.5 - 20000, -20000), a.from());
        assertEquals(new Point(1000 * 1.5 - 20000, -20000), a.to());
        assertEquals(2100, a.centre().distanceTo(a.to()), 1e-6);
        assertEquals(50, a.feed().programmed(), 1e-12);
    }

    @Test
    void bishopM30EndsTheProgramAndEmitsNothing() throws IOException {
        CheckedBlock b = Run.thesis(read("bishop.nc")).line(60);
        assertEquals(List.of(), b.before());
        assertEquals(List.of(), b.after());
        assertEquals(List.of(), b.motions());
    }
}
