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
 * expansions of cycles, compensation and chamfers, all written by gcnc) reads into its commands
 * without a fault and prints back to the same characters; and a packed file's commands pack again
 * into its own lines (the sender downloads what the compile wrote). The thesis's own Table 5.2 is
 * among them: golden/bishop.thesis-2004.thesis.dmc is its bytes (GoldenTest holds the two equal
 * beside ../shared).
 */
class RoundTripTest {
    @Test
    void everyLineGcncWritesAndTable52PrintsBackAsItWasRead() throws IOException {
        List<Path> files = new ArrayList<>();
        try (Stream<Path> s = Files.walk(Path.of("src/test/resources"))) {
            s.filter(p -> p.toString().endsWith(".dmc")).sorted().forEach(files::add);
        }
        assertTrue(files.contains(Path.of("src/test/resources/golden/bishop.thesis-2004.thesis.dmc")), "Table 5.2");
        assertTrue(files.size() > 40, "the test holds the goldens: " + files.size());
        int lines = 0;
        int packedFiles = 0;
        for (Path f : files) {
            int n = 0;
            List<String> all = Files.readAllLines(f);
            List<Instruction> commands = new ArrayList<>();
            for (String line : all) {
                n++;
                String at = f + ":" + n;
                List<String> printed = new ArrayList<>();
                for (String statement : DmcReader.statements(line)) {
                    Command c = DmcReader.read(statement, (code, args) -> {
                        throw new AssertionError(at + ": " + code + " " + java.util.Arrays.toString(args));
                    });
                    assertNotNull(c, at);
                    printed.add(DmcPrinter.print(c));
                    commands.add(new Instruction(c, Source.NONE));
                }
                assertEquals(line, String.join(";", printed), at);
                lines++;
            }
            // the DMC corpus is written by hand, a case a line (gcnc.DmcCorpus): read and printed back, not packed
            if (!f.startsWith(gcnc.DmcCorpus.DIR) && all.stream().anyMatch(l -> l.contains(";"))) {
                packedFiles++;
                assertEquals(all, LinePacker.pack(commands, 80).stream().map(LinePacker.Line::text).toList(), f.toString());
            }
        }
        assertTrue(lines > 2000, "lines read: " + lines);
        assertTrue(packedFiles >= 8, "packed files (the galil goldens): " + packedFiles);
    }

    @Test
    void aPackedLineBreaksWhereTheControllerMustStartOrStopOne() {
        List<Instruction> in = new ArrayList<>();
        for (Command c : List.of(new Command.Label("GCNC"), new Command.ServoHere("XY"), new Command.SetVariable("gline", 7),
                new Command.VectorSpeed(Fixed.of(2000)), new Command.VectorPosition(10, 20), new Command.VectorEnd(),
                new Command.BeginSequence(), new Command.AwaitSequence(), new Command.Output(1, true),
                new Command.Remark("NO A NOTE"), new Command.Wait(2000), new Command.Output(2, false), new Command.End(),
                new Command.Label("FAULT"), new Command.Stop(), new Command.End())) {
            in.add(new Instruction(c, Source.NONE));
        }
        assertEquals(List.of("#GCNC;SH XY;gline=7;VS 2000;VP 10,20;VE;BGS;AMS", "SB1", "NO A NOTE", "WT 2000", "CB2;EN",
                "#FAULT;ST;EN"), LinePacker.pack(in, 80).stream().map(LinePacker.Line::text).toList());
        List<Instruction> many = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            many.add(new Instruction(new Command.VectorPosition(100000 + i, -200000 - i), Source.NONE));
        }
        List<LinePacker.Line> lines = LinePacker.pack(many, 80);
        assertTrue(lines.stream().allMatch(l -> l.text().length() <= 80), "no line longer than the controller's 80");
        assertTrue(lines.stream().limit(lines.size() - 1).allMatch(l -> l.text().length() > 80 - 22), "each line filled");
        assertEquals(many, lines.stream().flatMap(l -> l.instructions().stream()).toList(), "in order, none lost");
        assertEquals(List.of("MG \"A;B\"", "NO X;Y"), DmcReader.statements("MG \"A;B\";NO X;Y"),
                "a ; inside quotes or a comment does not split");
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
    void theMachineCommandsPrintAndReadBack() {
        Command[] all = {
            new Command.AnalogOut(3001, Fixed.exactly(3, 4)),
            new Command.AxisSetting(Command.Setting.KP, 2, Fixed.of(0)),
            new Command.AxisSetting(Command.Setting.ER, 3, Fixed.of(-1)),
            new Command.SoftLimit(false, 'X', -5000, 'Y', -2500),
            new Command.SoftLimit(true, 'Y', 107500, 'Z', 285000),
            new Command.Jump("FAULT", java.util.Optional.empty()),
            new Command.Jump("NOHOME", java.util.Optional.of(new Command.Condition.PositionOff('X', 340000, 10))),
            new Command.Jump("NOHOME", java.util.Optional.of(new Command.Condition.PositionOff('Y', -105000, 10))),
            new Command.Jump("NOHOME", java.util.Optional.of(new Command.Condition.PositionOff('Y', 0, 1))),
            new Command.Jump("SPOK", java.util.Optional.of(new Command.Condition.InputIs(3, true))),
            new Command.Jump("SPW", java.util.Optional.of(new Command.Condition.Before("twt"))),
            new Command.Call("TURRET"),
            new Command.Message("NOT AT HOME", List.of()),
            new Command.Message("COMMAND ERROR AT G-CODE LINE", List.of("gline", "_TC")),
            new Command.Stop(), new Command.Abort(), new Command.ClearStack(),
            new Command.SetVariable("gline", 120), new Command.SetDeadline("twt", 8000)};
        for (Command c : all) {
            assertEquals(c, read(DmcPrinter.print(c)), DmcPrinter.print(c));
        }
        assertEquals("JP #NOHOME,@ABS[_TPY+105000]>10", DmcPrinter.print(all[7]));
        assertEquals("BL -5000,-2500", DmcPrinter.print(all[3]));
        assertEquals("FL ,107500,285000", DmcPrinter.print(all[4]));
        assertEquals("ER ,,,-1", DmcPrinter.print(all[2]));
    }

    @Test
    void whatItCannotReadIsReportedNotGuessed() {
        for (String bad : new String[] {"VP 1.5,2", "CR -5,0,90", "OF ,,12", "WT -1", "SB", "GA C", "VS 0", "#9X",
            "AO 1,12", "AO 5,1.5", "AO 9000,1", "KP 1,2", "BL 5", "JP #A,x>1", "JS #A,@IN[1]=1", "MG text", "AB", "ST X", "ZS 1"}) {
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
