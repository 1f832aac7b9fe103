package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * {@code --stock} values without a unit are in the program's units when its head says G20 or G21
 * (issue 34 item 3), and the command says which on standard error; a value with its unit keeps it;
 * a program that says neither, or one on standard input, is read in millimetres, said too. The
 * blank simulated is read back from the setup sheet's Blank row.
 */
class StockUnitsTest {
    static final String INCH = WearOffsetsTest.INCH;
    static final String METRIC = WearOffsetsTest.METRIC;

    static Path write(String name, String text) throws Exception {
        Path p = Files.createTempDirectory("gcnc-stock-units").resolve(name);
        Files.writeString(p, text);
        return p;
    }

    /** The sheet's Blank row for {@code program} with {@code --stock stock}, and the command's standard error. */
    static String[] blank(Path program, String machine, String stock) throws Exception {
        Path html = program.resolveSibling("sheet.html");
        CliTest.Run r = CliTest.gcnc("sheet", program.toString(), "--machine", machine, "--stock", stock, "-o", html.toString());
        assertEquals(0, r.status(), r.err());
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("<th>Blank</th><td>([^<]*)</td>").matcher(Files.readString(html));
        assertTrue(m.find());
        return new String[] {m.group(1), r.err()};
    }

    @Test
    void onAG20ProgramPlainNumbersAreInches() throws Exception {
        String[] b = blank(write("inch.nc", INCH), "haas", "1.75,4,2");
        assertEquals("diameter 1.75 in (44.45 mm), length 4 in (101.6 mm); sticks out 2 in (50.8 mm) from the jaws' face", b[0]);
        assertTrue(b[1].contains("gcnc: --stock 1.75,4,2: the values without a unit are in inches, the program's units"
                + " (G20 at line 2)"), b[1]);
        // a value with its unit keeps it
        b = blank(write("inch.nc", INCH), "haas", "1.75,4,50.8mm");
        assertTrue(b[0].endsWith("sticks out 2 in (50.8 mm) from the jaws' face"), b[0]);
        // every value with its unit: nothing to say
        b = blank(write("inch.nc", INCH), "haas", "1.75in,4in,2in");
        assertTrue(b[0].startsWith("diameter 1.75 in (44.45 mm)"), b[0]);
        assertTrue(!b[1].contains("--stock"), b[1]);
    }

    @Test
    void onAG21ProgramPlainNumbersAreMillimetres() throws Exception {
        String[] b = blank(write("metric.nc", METRIC), "fanuc", "65,150,100");
        assertEquals("diameter 65 mm, length 150 mm; sticks out 100 mm from the jaws' face", b[0]);
        assertTrue(b[1].contains("gcnc: --stock 65,150,100: the values without a unit are in millimetres, the program's units"
                + " (G21 at line 2)"), b[1]);
        b = blank(write("metric.nc", METRIC), "fanuc", "2.5in,150,100");
        assertEquals("diameter 63.5 mm, length 150 mm; sticks out 100 mm from the jaws' face", b[0]);
    }

    @Test
    void aProgramThatSaysNeitherIsReadInMillimetresAndSaysSo() throws Exception {
        // the inch part without its G20: the Haas is in inches at power-up, but --stock does not guess from that
        String[] b = blank(write("unsaid.nc", INCH.replace("G20 G99", "G99")), "haas", "44.45,101.6,50.8");
        assertEquals("diameter 1.75 in (44.45 mm), length 4 in (101.6 mm); sticks out 2 in (50.8 mm) from the jaws' face", b[0]);
        assertTrue(b[1].contains("the values without a unit are in millimetres: the program says neither G20 nor G21 before"
                + " its first move"), b[1]);
        // a G20 after the first move is not the program's head
        b = blank(write("late.nc", INCH.replace("G20 G99", "G99").replace("G01 Z-1.", "G20 G01 Z-1.")), "haas",
                "44.45,101.6,50.8");
        assertTrue(b[0].startsWith("diameter 1.75 in (44.45 mm)"), b[0]);
    }

    @Test
    void onStandardInputPlainNumbersAreMillimetresAndItSaysWhy() throws Exception {
        RunOnControllerTest.Run r = RunOnControllerTest.gcnc(METRIC, "simulate", "-", "--machine", "fanuc", "--stock", "65,150,100");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().contains("millimetres: a program on standard input is not looked at first"), r.err());
    }

    @Test
    void inSpanishTooAndTheUnitWordsAreSpanish() throws Exception {
        Path p = write("inch.nc", INCH);
        CliTest.Run r = CliTest.gcnc("simulate", p.toString(), "--machine", "haas", "--stock", "1.75,4,2", "--lang", "es");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().contains("--stock 1.75,4,2: los valores sin unidad están en pulgadas, las unidades del programa"
                + " (G20 en la línea 2)"), r.err());
    }
}
