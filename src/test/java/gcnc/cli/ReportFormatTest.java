package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.networknt.schema.JsonSchema;
import com.networknt.schema.JsonSchemaFactory;
import com.networknt.schema.SpecVersion;
import com.networknt.schema.ValidationMessage;
import gcnc.diag.Code;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** --format json and --format sarif: one document on standard output, every finding in it, nothing lost. */
class ReportFormatTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final JsonSchema SARIF_SCHEMA = sarifSchema();

    private static JsonSchema sarifSchema() {
        try (InputStream in = ReportFormatTest.class.getResourceAsStream("/sarif/sarif-schema-2.1.0.json")) {
            return JsonSchemaFactory.getInstance(SpecVersion.VersionFlag.V4).getSchema(in);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    static void assertValidSarif(JsonNode doc) {
        Set<ValidationMessage> problems = SARIF_SCHEMA.validate(doc);
        assertEquals(Set.of(), problems, doc.toPrettyString());
    }

    private final Path dir = Files.createTempDirectory("gcnc-report");

    ReportFormatTest() throws IOException {
    }

    @Test
    void jsonHasEveryFindingWithItsPlaceCodeMessageAndArguments() throws IOException {
        CliTest.Run gnu = CliTest.gcnc("check", "docs/examples/mistakes.nc");
        CliTest.Run r = CliTest.gcnc("check", "--format", "json", "docs/examples/mistakes.nc", "samples/turning.nc");
        assertEquals(1, r.status(), r.err());
        JsonNode doc = JSON.readTree(r.out());
        assertEquals("gcnc-diagnostics", doc.get("format").asText());
        assertEquals(1, doc.get("version").asInt());
        // every line a finding but the last: the hint to gcnc explain (ExplainHintTest)
        String[] lines = gnu.err().substring(0, gnu.err().lastIndexOf("For more information")).split("\n");
        JsonNode all = doc.get("diagnostics");
        assertEquals(lines.length, all.size(), "the JSON holds exactly the findings the GNU format prints");
        for (int i = 0; i < lines.length; i++) {
            JsonNode d = all.get(i);
            String expected = d.get("file").asText() + ":" + d.get("line").asInt() + ":" + d.get("column").asInt() + ": "
                    + d.get("severity").asText() + "[" + d.get("code").asText() + "]: " + d.get("message").asText();
            assertEquals(lines[i], expected);
            assertTrue(d.get("arguments").isArray());
        }
        assertEquals(lines.length, doc.get("errors").asInt());
        assertTrue(r.err().contains("docs/examples/mistakes.nc: 14 blocks, 5 errors"), r.err());
        assertTrue(r.err().contains("samples/turning.nc: 13 blocks, no errors"), "summaries move to standard error");
    }

    /** {@code --corners N}: the N slowest corners after the summary, and the same list in the JSON's simulation. */
    @Test
    void theCornerReportListsTheSlowestCornersInTextAndJson() throws IOException {
        String program = "src/test/resources/plan/corners.fanuc.nc";
        CliTest.Run text = CliTest.gcnc("compile", "--machine", "fanuc", "--stock", "none", program, "--corners", "3",
                "-o", dir.resolve("c.dmc").toString());
        assertEquals(0, text.status(), text.err());
        String said = text.err() + text.out();
        assertTrue(said.contains("slowest 3 corners:\n  " + program + ":13 N60: 0.0 mm/min where the moves run at 4999.9:"
                + " the path turns back (180.0°): the machine stops\n  " + program + ":8 N10: "), said);
        CliTest.Run json = CliTest.gcnc("compile", "--machine", "fanuc", "--stock", "none", program, "--corners", "7",
                "--format", "json", "-o", dir.resolve("c.dmc").toString());
        JsonNode corners = JSON.readTree(json.out()).get("simulations").get(0).get("corners");
        assertEquals(7, corners.size(), json.out());
        assertEquals("reversal", corners.get(0).get("why").asText());
        assertEquals(13, corners.get(0).get("line").asInt());
        assertEquals("60", corners.get(0).get("number").asText());
        assertEquals("acceleration", corners.get(4).get("why").asText());
        assertEquals(0.02, corners.get(4).get("lengthMm").asDouble(), 1e-9);
        assertEquals("arc", corners.get(5).get("why").asText());
        // without the option neither is written; beyond 100 is a usage error
        CliTest.Run plain = CliTest.gcnc("compile", "--machine", "fanuc", "--stock", "none", program, "--format", "json",
                "-o", dir.resolve("c.dmc").toString());
        assertFalse(JSON.readTree(plain.out()).get("simulations").get(0).has("corners"), plain.out());
        assertEquals(2, CliTest.gcnc("compile", "--machine", "fanuc", program, "--corners", "101",
                "-o", dir.resolve("c.dmc").toString()).status());
    }

    @Test
    void jsonKeepsArgumentsAndNamesExactlyEvenWithControlCharacters() throws IOException {
        Path p = dir.resolve("tab\there.nc");
        Files.writeString(p, "G21\nG01 X10. Z5. $\nM30\n");
        CliTest.Run r = CliTest.gcnc("check", "--format", "json", p.toString());
        JsonNode d = JSON.readTree(r.out()).get("diagnostics");
        assertEquals(p.toString(), d.get(0).get("file").asText());
        boolean dollar = false;
        for (JsonNode x : d) {
            dollar |= x.get("code").asText().equals("E003") && x.get("arguments").toString().contains("$");
        }
        assertTrue(dollar, r.out());
    }

    @Test
    void sarifIsValidAgainstTheOfficialSchemaAndAnnotatesTheLines() throws IOException {
        Path spaced = dir.resolve("my part é.nc");
        Files.writeString(spaced, "G21\nG01 X10. Z5. $\nM30\n");
        CliTest.Run r = CliTest.gcnc("check", "--format", "sarif", "docs/examples/mistakes.nc", spaced.toString(), "no/such.nc");
        assertEquals(2, r.status(), r.err());
        JsonNode doc = JSON.readTree(r.out());
        assertValidSarif(doc);
        JsonNode run = doc.get("runs").get(0);
        JsonNode rules = run.get("tool").get("driver").get("rules");
        assertEquals(Code.values().length, rules.size(), "one rule per diagnostic code");
        Set<String> ruleIds = new HashSet<>();
        rules.forEach(rule -> ruleIds.add(rule.get("id").asText()));
        JsonNode first = run.get("results").get(0);
        assertTrue(ruleIds.contains(first.get("ruleId").asText()));
        assertEquals(first.get("ruleId").asText(), rules.get(first.get("ruleIndex").asInt()).get("id").asText());
        assertEquals("error", first.get("level").asText());
        JsonNode loc = first.get("locations").get(0).get("physicalLocation");
        assertEquals("docs/examples/mistakes.nc", loc.get("artifactLocation").get("uri").asText());
        assertEquals("%SRCROOT%", loc.get("artifactLocation").get("uriBaseId").asText());
        assertTrue(loc.get("region").get("startLine").asInt() >= 1);
        String all = r.out();
        assertTrue(all.contains("\"uri\": \"file://" + dir.toString().replace(" ", "%20") + "/my%20part%20%C3%A9.nc\""), all);
        assertTrue(all.contains("\"uri\": \"no/such.nc\""), "an unreadable file is a result too");
        assertTrue(all.contains("\"ruleId\": \"E500\""), all);
    }

    /** SARIF rules carry gcnc explain's prose: why as fullDescription, the fix and an example as help. */
    @Test
    void sarifRulesHaveAFullDescriptionAndHelpFromTheExplanations() throws IOException {
        CliTest.Run r = CliTest.gcnc("check", "--format", "sarif", "docs/examples/mistakes.nc");
        JsonNode doc = JSON.readTree(r.out());
        assertValidSarif(doc);
        JsonNode rule = null;
        for (JsonNode x : doc.get("runs").get(0).get("tool").get("driver").get("rules")) {
            if (x.get("id").asText().equals("E051")) {
                rule = x;
            }
        }
        assertTrue(rule.get("fullDescription").get("text").asText().startsWith("A feed move before the spindle"),
                rule.toString());
        assertTrue(rule.get("help").get("text").asText().startsWith("Fix: Start the spindle with M03"), rule.toString());
        assertTrue(rule.get("help").get("text").asText().contains("Example:\nG21 G99\nG01 X20. Z-5. F0.2"),
                rule.toString());
        assertTrue(rule.get("help").get("markdown").asText().contains("```gcode\nG21 G99\n"), rule.toString());
        CliTest.Run es = CliTest.gcnc("check", "--lang", "es", "--format", "sarif", "docs/examples/mistakes.nc");
        assertTrue(es.out().contains("\"text\": \"Arreglo: Arranque el husillo"), es.out());
    }

    /** The validator is not vacuous: a level SARIF does not have, or a missing ruleId's message, is caught. */
    @Test
    void theSchemaRejectsWhatSarifForbids() throws IOException {
        CliTest.Run r = CliTest.gcnc("check", "--format", "sarif", "docs/examples/mistakes.nc");
        String broken = r.out().replaceFirst("\"level\": \"error\"", "\"level\": \"fatal\"");
        assertFalse(SARIF_SCHEMA.validate(JSON.readTree(broken)).isEmpty());
        String noVersion = r.out().replaceFirst("\"version\": \"2.1.0\"", "\"version\": \"2.0\"");
        assertFalse(SARIF_SCHEMA.validate(JSON.readTree(noVersion)).isEmpty());
    }

    @Test
    void aCleanRunIsAnEmptyValidSarifLog() throws IOException {
        CliTest.Run r = CliTest.gcnc("check", "--format", "sarif", "samples/turning.nc");
        assertEquals(0, r.status(), r.err());
        JsonNode doc = JSON.readTree(r.out());
        assertValidSarif(doc);
        assertEquals(0, doc.get("runs").get(0).get("results").size());
    }

    /** A broken profile is a finding in the document too, at the profile's own line. */
    @Test
    void aBrokenProfileIsAResultAtTheProfilesLine() throws IOException {
        Path bad = dir.resolve("bad.machine");
        Files.writeString(bad, Files.readString(Path.of("tables/machines/generic.machine")).replace("x.sign = 1", "x.sign = up"));
        CliTest.Run r = CliTest.gcnc("compile", "--format", "sarif", "--machine", bad.toString(), "samples/turning.nc",
                "-o", dir.resolve("x.dmc").toString());
        assertEquals(2, r.status(), r.err());
        JsonNode doc = JSON.readTree(r.out());
        assertValidSarif(doc);
        JsonNode result = doc.get("runs").get(0).get("results").get(0);
        assertEquals("E400", result.get("ruleId").asText());
        assertTrue(result.get("message").get("text").asText().contains("'up' is not a number"), r.out());
        assertFalse(Files.exists(dir.resolve("x.dmc")));
    }

    @Test
    void simulateFindingsAreReportedInSarif() throws IOException {
        CliTest.Run r = CliTest.gcnc("simulate", "--format", "sarif", "--quiet", "samples/turning.nc");
        assertEquals(0, r.status(), r.err());
        assertValidSarif(JSON.readTree(r.out()));
        assertEquals("", r.err(), "--quiet: no summary");
    }

    @Test
    void quietLeavesTheFindingsAndDropsTheSummaries() {
        CliTest.Run r = CliTest.gcnc("check", "--quiet", "docs/examples/mistakes.nc", "samples/turning.nc");
        assertEquals(1, r.status());
        assertEquals("", r.out());
        assertEquals(5, r.err().split("\n").length, r.err());
    }

    @Test
    void sarifBracesInMessagesAreDoubledAsTheStandardAsks() throws IOException {
        Path p = dir.resolve("braces.nc");
        Files.writeString(p, "G21\nG01 X10. Z5. {\nM30\n");
        CliTest.Run r = CliTest.gcnc("check", "--format", "sarif", p.toString());
        JsonNode doc = JSON.readTree(r.out());
        assertValidSarif(doc);
        for (JsonNode result : doc.get("runs").get(0).get("results")) {
            String text = result.get("message").get("text").asText();
            assertFalse(text.replace("{{", "").replace("}}", "").contains("{"), text);
        }
    }
}
