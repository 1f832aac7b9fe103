package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** gcnc path on the command line: the golden's CSV on standard output or in OUT, JSON Lines, nothing for a faulty program. */
class PathCommandTest {
    private static final String BISHOP_GOLDEN = "src/test/resources/golden/path/bishop.thesis-2004.csv";

    @Test
    void printsTheBishopsPathAsItsGoldenAndWritesOutWhole() throws Exception {
        Path csv = Files.createTempDirectory("gcnc-path").resolve("bishop.csv");
        CliTest.Run r = CliTest.gcnc("path", "--machine", "thesis-2004", "samples/bishop.nc", "-o", csv.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals(Files.readString(Path.of(BISHOP_GOLDEN)), Files.readString(csv));
        assertTrue(r.err().contains("samples/bishop.nc: 59 blocks -> " + csv + " (57 moves)"), r.err());
        Path out = csv.resolveSibling("bishop.json");
        CliTest.Run json = CliTest.gcnc("path", "--machine", "thesis-2004", "--format", "json", "samples/bishop.nc",
                "-o", out.toString());
        assertEquals(0, json.status(), json.err());
        String first = Files.readAllLines(out).get(0);
        assertTrue(first.startsWith("{\"kind\":\"rapid\",\"file\":\"samples/bishop.nc\",\"line\":2,\"block\":\"N100\","), first);
        assertEquals(57, Files.readAllLines(out).size());
    }

    @Test
    void aProgramWithAnErrorWritesNothing() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-path");
        Path p = dir.resolve("bad.nc");
        Files.writeString(p, "G21 G40 G99\nG50 S2000\nT0101\nG97 S500 M03\nG00 X50. Z2.\nG01 X F0.2\nM30\n");
        CliTest.Run r = CliTest.gcnc("path", p.toString(), "-o", dir.resolve("bad.csv").toString());
        assertEquals(1, r.status(), r.err());
        assertTrue(r.err().contains("error[E006]"), r.err());
        assertFalse(Files.exists(dir.resolve("bad.csv")));
        assertEquals(2, CliTest.gcnc("path", "--format", "xml", p.toString()).status());
        assertEquals(2, CliTest.gcnc("path", p.toString(), "-o", p.toString()).status(), "never the program itself");
    }
}
