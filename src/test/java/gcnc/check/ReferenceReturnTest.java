package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * G30 (Fanuc 0i-TF): to the profile's second reference point through the intermediate point the
 * words give, the axes not named staying there; a machine without {@code reference.N} is E631.
 */
class ReferenceReturnTest {
    private static final String HEAD = "G21 G99\nT0101\nG97 S1000 M03\nG00 X60. Z5.\n";

    /** The fanuc machine with its second reference point at X150 Z400 mm (a radius). */
    static MachineProfile withReference() throws Exception {
        String text = Files.readString(Path.of("tables/machines/fanuc.machine"), StandardCharsets.UTF_8).lines()
                .filter(l -> !l.startsWith("name ")).collect(Collectors.joining("\n"));
        Path p = Files.createTempFile("fanuc-g30", ".machine");
        Files.writeString(p, "name = fanuc-g30\n" + text + "\nreference.2 = 150, 400\n", StandardCharsets.UTF_8);
        try {
            return ProfileLoader.load(p.toString(), TableSource.builtIn(), Run.TABLES);
        } finally {
            Files.delete(p);
        }
    }

    /** The rapids' ends in machine mm, "X Z" (X a radius). */
    private static String ends(Run r) {
        return r.blocks.stream().flatMap(b -> b.motions().stream()).filter(m -> m instanceof Motion.Linear)
                .map(m -> ((Motion.Linear) m).to()).map(q -> Math.round(q.x() / 500.0) + " " + Math.round(q.z() / 500.0))
                .collect(Collectors.joining(", "));
    }

    @Test
    void g30GoesToTheSecondReferenceThroughTheIntermediatePoint() throws Exception {
        MachineProfile p = withReference();
        // G54 is at machine X0 Z100: X60. Z5. is X30 Z105 mm; U0 W0 keeps it as the intermediate point
        Run both = Run.of(p, HEAD + "G30 U0. W0.\nM30\n", Checker.ERROR_CAP);
        assertEquals("", both.errors());
        assertEquals("30 105, 30 105, 150 400", ends(both));
        // X only: Z stays at the intermediate point; P2 is the default
        Run x = Run.of(p, HEAD + "G30 P2 U10.\nM30\n", Checker.ERROR_CAP);
        assertEquals("30 105, 35 105, 150 105", ends(x));
    }

    @Test
    void aReferenceTheProfileDoesNotGiveOrAWrongPIsAnError() throws Exception {
        assertEquals("5:1:E631", Run.of("fanuc", HEAD + "G30 U0.\nM30\n").errors());
        MachineProfile p = withReference();
        assertEquals("5:1:E631", Run.of(p, HEAD + "G30 P3 U0.\nM30\n", Checker.ERROR_CAP).errors());
        assertEquals("5:5:E630", Run.of(p, HEAD + "G30 P5 U0.\nM30\n", Checker.ERROR_CAP).errors());
        assertEquals("5:1:E030", Run.of(p, HEAD + "G30\nM30\n", Checker.ERROR_CAP).errors());
        // the Haas lathe has no G30
        assertEquals("5:1:E011", Run.of("haas", "G21 G99\nT101\nG97 S1000 M03\nG00 X60. Z5.\nG30 U0.\nM30\n").errors());
    }

    /** Under G41/G42 it is a temporary cancel, as G28 (E620). */
    @Test
    void underCompensationItCancelsTheOffsetForItsMoves() throws Exception {
        Run r = Run.of(withReference(), HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nG30 U0. W0.\nG40 G00 X60. Z5.\nM30\n",
                Checker.ERROR_CAP);
        assertEquals("7:1:E620", r.errors());
    }
}
