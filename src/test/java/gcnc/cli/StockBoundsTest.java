package gcnc.cli;

import static gcnc.cli.CliTest.gcnc;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.cli.CliTest.Run;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * A blank larger than the machine holds is a located error naming the limit, never a stack trace, a
 * DMC that cannot be replayed or a full heap (issue 35: {@code (1e999 40)} threw
 * NegativeArraySizeException in sim.Material, a 400-digit diameter compiled to NO STOCK
 * D922337203685477.5807, {@code --stock 40,1e9} filled a 6 GB heap).
 */
class StockBoundsTest {
    private static final String BODY = "G21 G99\nT0101\nG97 S500 M03\nG00 X50. Z2.\nG01 Z-5. F0.2\nG00 X60.\nM30\n";

    @Test
    void aHugeNumberInTheStockHeaderIsE511AtLineOne() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-stock");
        Path inf = Files.writeString(dir.resolve("inf.nc"), "(1e999 40)\n" + BODY);
        Run r = gcnc("compile", inf.toString(), "--machine", "haas");
        assertEquals(1, r.status(), r.err());
        assertTrue(r.err().contains(inf + ":1:1: error[E513]: the blank's length Infinity mm is more than gcnc models"
                + " on machine haas: at most 5330 mm"), r.err());
        assertFalse(Files.exists(dir.resolve("inf.dmc")));
        Path wide = Files.writeString(dir.resolve("wide.nc"), "(100. 1" + "0".repeat(400) + ".)\n" + BODY);
        r = gcnc("compile", wide.toString(), "--machine", "haas");
        assertEquals(1, r.status(), r.err());
        assertTrue(r.err().contains(wide + ":1:1: error[E511]: the blank's diameter Infinity mm is more than machine haas holds: at most 424 mm"), r.err());
        assertFalse(Files.exists(dir.resolve("wide.dmc")), "a DMC with NO STOCK D922337203685477.5807 is not written");
        // a blank the machine holds is as before
        Path fine = Files.writeString(dir.resolve("fine.nc"), "(100. 60.)\n" + BODY);
        assertEquals(0, gcnc("compile", fine.toString(), "--machine", "haas").status());
    }

    @Test
    void aStockOptionLargerThanTheMachineIsAUsageErrorNamingTheLimit() {
        Run r = gcnc("simulate", "samples/turning.nc", "--machine", "haas", "--stock", "40,1e9");
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("--stock: the length 1000000000 mm is more than 10 times the Z travel's length on machine"
                + " haas: at most 5330 mm (E513)"), r.err());
        r = gcnc("simulate", "samples/turning.nc", "--machine", "haas", "--stock", "1000,100");
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("at most 424 mm (E511)"), r.err());
    }
}
