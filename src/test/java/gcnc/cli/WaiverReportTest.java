package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** A waived finding in each report format (issue 31): a GNU note, JSON's "waived", a SARIF suppression; counted apart. */
class WaiverReportTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String PROGRAM = "src/test/resources/waivers/g70-u.fanuc.nc";
    private static final String REASON = "our post writes U and W in every G70; the control ignores them";

    @Test
    void gnuSaysWaivedWithTheReasonAndTheSummaryCountsIt() {
        CliTest.Run r = CliTest.gcnc("check", "--machine", "fanuc", PROGRAM);
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().contains(PROGRAM + ":13:13: note[E642] waived: " + REASON + ": G70: U0.4 does nothing in a G70"),
                r.err());
        assertTrue(r.out().contains(PROGRAM + ": 13 blocks, no errors, 1 waived"), r.out());
        assertFalse(r.err().contains("gcnc explain E642"), "a waived finding is not what the closing hint names");
    }

    @Test
    void aWaivedErrorDoesNotFailTheCheck() throws IOException {
        Path p = Files.createTempDirectory("gcnc-waiver").resolve("p.nc");
        String program = "G21 G40 G99\nG50 S2000\nT0101\nG97 S500 M03\nG00 X50. Z2.\nG01 X F0.2%s\nM30\n";
        Files.writeString(p, String.format(program, ""));
        assertEquals(1, CliTest.gcnc("check", p.toString()).status());
        Files.writeString(p, String.format(program, " (GCNC ALLOW E006: the control reads it)"));
        CliTest.Run r = CliTest.gcnc("check", p.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("no errors, 1 waived"), r.out());
        CliTest.Run c = CliTest.gcnc("compile", p.toString(), "-o", p.resolveSibling("p.dmc").toString());
        assertEquals(1, c.status(), c.err());
        assertTrue(c.err().contains("error[E675]"), c.err());
        assertFalse(Files.exists(p.resolveSibling("p.dmc")));
    }

    @Test
    void jsonHasTheReasonAndAWaivedCount() throws IOException {
        CliTest.Run r = CliTest.gcnc("check", "--machine", "fanuc", "--format", "json", PROGRAM);
        JsonNode doc = JSON.readTree(r.out());
        assertEquals(0, doc.get("warnings").asInt(), r.out());
        assertEquals(1, doc.get("waived").asInt(), r.out());
        JsonNode d = doc.get("diagnostics").get(0);
        assertEquals("E642", d.get("code").asText());
        assertEquals("warning", d.get("severity").asText());
        assertEquals(REASON, d.get("waived").asText());
    }

    @Test
    void sarifHasAnInSourceSuppressionWithTheJustificationAndIsValid() throws IOException {
        CliTest.Run r = CliTest.gcnc("check", "--machine", "fanuc", "--format", "sarif", PROGRAM);
        JsonNode doc = JSON.readTree(r.out());
        ReportFormatTest.assertValidSarif(doc);
        JsonNode result = doc.get("runs").get(0).get("results").get(0);
        assertEquals("E642", result.get("ruleId").asText());
        JsonNode s = result.get("suppressions").get(0);
        assertEquals("inSource", s.get("kind").asText());
        assertEquals(REASON, s.get("justification").asText());
    }
}
