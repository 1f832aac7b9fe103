package gcnc.dmc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * One printer and one reader: every line of every DMC file the tests hold (the goldens, the
 * expansions of cycles, compensation and chamfers, all written by gcnc) and of the thesis's own
 * Table 5.2 reads into a command without a fault and prints back to the same characters.
 */
class RoundTripTest {
    private static final Path TABLE_5_2 = Path.of("../shared/spec/bishop.expected.dmc");

    @Test
    void everyLineGcncWritesAndTable52PrintsBackAsItWasRead() throws IOException {
        List<Path> files = new ArrayList<>();
        try (Stream<Path> s = Files.walk(Path.of("src/test/resources"))) {
            s.filter(p -> p.toString().endsWith(".dmc")).sorted().forEach(files::add);
        }
        files.add(TABLE_5_2);
        assertTrue(files.size() > 40, "the test holds the goldens: " + files.size());
        int lines = 0;
        for (Path f : files) {
            int n = 0;
            for (String line : Files.readAllLines(f)) {
                n++;
                String at = f + ":" + n;
                Command c = DmcReader.read(line, (code, args) -> {
                    throw new AssertionError(at + ": " + code + " " + java.util.Arrays.toString(args));
                });
                assertNotNull(c, at);
                assertEquals(line, DmcPrinter.print(c), at);
                lines++;
            }
        }
        assertTrue(lines > 5000, "lines read: " + lines);
    }

    @Test
    void theFormsAHandEditedFileAddsReadAsTheirCommand() {
        assertEquals(new Command.BeginSequence(), read("BG S"));
        assertEquals(new Command.Output(1, true), read("SB 1"));
        assertEquals(new Command.VectorPosition(10, -20), read("  VP 10, -20  "));
        assertEquals(new Command.Remark("'a note"), read("'a note"));
        assertEquals(new Command.SourceMark(12), read("NO L12"));
        assertEquals(new Command.WaitPast(false, 'Z', new Command.Operand.Count(-500)), read("MF ,,-500"));
        assertEquals("MF ,,-500", DmcPrinter.print(read("MF ,,-500")));
    }

    @Test
    void whatItCannotReadIsReportedNotGuessed() {
        for (String bad : new String[] {"VP 1.5,2", "CR -5,0,90", "OF ,,12", "WT -1", "SB", "GA C", "VS 0", "#9X"}) {
            List<String> faults = new ArrayList<>();
            assertEquals(null, DmcReader.read(bad, (code, args) -> faults.add(code.name())), bad);
            assertEquals(List.of("E301_SIM_BAD_ARGUMENTS"), faults, bad);
        }
        List<String> faults = new ArrayList<>();
        assertEquals(null, DmcReader.read("FOO 1", (code, args) -> faults.add(code.name())));
        assertEquals(List.of("E300_SIM_UNKNOWN_INSTRUCTION"), faults);
    }

    private static Command read(String line) {
        return DmcReader.read(line, (code, args) -> {
            throw new AssertionError(line + ": " + code);
        });
    }
}
