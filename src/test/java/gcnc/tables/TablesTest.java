package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

class TablesTest {
    @Test
    void tablesSixToNine() {
        Tables t = Tables.builtIn();
        assertTrue(t.limit('N').orElseThrow().integer());
        assertEquals(9999999, t.limit('N').orElseThrow().upper());
        assertEquals(20, t.toolOffsets().size());
        assertEquals(0.2, t.toolOffsets().get(2).x(), 1e-12);
        assertEquals(20, t.workOffsets().size());
    }

    @Test
    void anEditedCopyIsReadWithoutRebuilding() throws Exception {
        Path dir = copyOfTables();
        Path e = dir.resolve("errors.csv");
        Files.writeString(e, Files.readString(e).replace("arc radius R{0}", "radius R{0}"));
        Tables t = Tables.load(TableSource.directory(dir));
        assertTrue(t.messages().template(gcnc.diag.Code.E101_ARC_RADIUS_TOO_SMALL, ErrorMessages.Lang.EN)
                .startsWith("radius R{0}"));
    }

    @Test
    void aBadValueIsReportedWhereItIs() throws Exception {
        Path dir = copyOfTables();
        Path m = dir.resolve("tool_offsets.csv");
        Files.writeString(m, Files.readString(m).replaceFirst("\n3,", "\n4,"));
        TableException e = assertThrows(TableException.class, () -> Tables.load(TableSource.directory(dir)));
        assertTrue(e.path().endsWith("tool_offsets.csv"));
    }

    /** Loads a copy of tables/ with one file's text changed; the fault it must give. */
    private static TableException faultWith(String file, java.util.function.UnaryOperator<String> edit) throws Exception {
        Path dir = copyOfTables();
        Path f = dir.resolve(file);
        Files.writeString(f, edit.apply(Files.readString(f)));
        TableException e = assertThrows(TableException.class, () -> Tables.load(TableSource.directory(dir)));
        assertEquals(f.toString(), e.path());
        return e;
    }

    private static int lineOf(String file, String start) throws IOException {
        return Files.readAllLines(Path.of("tables", file)).indexOf(
                Files.readAllLines(Path.of("tables", file)).stream().filter(l -> l.startsWith(start)).findFirst().orElseThrow()) + 1;
    }

    @Test
    void anErrorCodeListedTwiceIsAFault() throws Exception {
        TableException e = faultWith("errors.csv", t -> t + "48,error,again,otra vez\n");
        assertEquals("E048 is listed twice (first on line " + lineOf("errors.csv", "48,") + ")", e.english());
        assertEquals(1, e.diagnostic().span().column());
    }

    @Test
    void aWordListedTwiceInParameterLimitsIsAFault() throws Exception {
        TableException e = faultWith("parameter_limits.csv", t -> t + "X,P,D,-1,1\n");
        assertEquals("word X is listed twice (first on line " + lineOf("parameter_limits.csv", "X,") + ")",
                e.english());
    }

    @Test
    void signAndTypeAreOneOfTwoLetters() throws Exception {
        TableException e = faultWith("parameter_limits.csv", t -> t.replace("\nS,N,E,", "\nS,n,E,"));
        assertEquals("sign is P or N (not 'n')", e.english());
        assertEquals(lineOf("parameter_limits.csv", "S,"), e.diagnostic().span().line());
        assertEquals(3, e.diagnostic().span().column());
    }

    @Test
    void nanIsNotANumberInATable() throws Exception {
        TableException e = faultWith("parameter_limits.csv", t -> t.replace("\nF,N,D,0.0001,", "\nF,N,D,NaN,"));
        assertEquals("'NaN' is not a number (lower)", e.english());
        e = faultWith("tool_offsets.csv", t -> t.replace("\n2,00.100,", "\n2,Infinity,"));
        assertEquals("'Infinity' is not a number (x)", e.english());
    }

    @Test
    void aTemplateThatCannotBeRenderedIsAFaultAtItsBrace() throws Exception {
        TableException e = faultWith("errors.csv", t -> t.replace("arc radius R{0} cannot", "arc radius R{0 cannot"));
        assertEquals("message template cannot be rendered: '{' without '}'", e.english());
        assertEquals(lineOf("errors.csv", "101,"), e.diagnostic().span().line());
        assertEquals("101,error,arc radius R".length() + 1, e.diagnostic().span().column());
    }

    @Test
    void aPlaceholderThatIsNotANumberIsAFault() throws Exception {
        TableException e = faultWith("errors.csv", t -> t.replace("El radio R{0}", "El radio R{cero}"));
        assertEquals("message template cannot be rendered: '{cero}' is not a placeholder {0}, {1}...",
                e.english());
        assertEquals(lineOf("errors.csv", "101,"), e.diagnostic().span().line());
    }

    @Test
    void everyCodeNeedsARow() throws Exception {
        TableException e = faultWith("errors.csv", t -> t.replaceFirst("\n314,[^\n]*", ""));
        assertEquals("no row for E314: every diagnostic code needs its English and Spanish text", e.english());
    }

    @Test
    void aByteOrderMarkIsAcceptedInATable() throws Exception {
        Path dir = copyOfTables();
        Path f = dir.resolve("parameter_limits.csv");
        byte[] text = Files.readAllBytes(f);
        byte[] withBom = new byte[text.length + 3];
        withBom[0] = (byte) 0xEF;
        withBom[1] = (byte) 0xBB;
        withBom[2] = (byte) 0xBF;
        System.arraycopy(text, 0, withBom, 3, text.length);
        Files.write(f, withBom);
        assertEquals(99999, Tables.load(TableSource.directory(dir)).limit('S').orElseThrow().upper());
    }

    @Test
    void aByteThatIsNotUtf8IsAFaultInATable() throws Exception {
        Path dir = copyOfTables();
        Path f = dir.resolve("errors.csv");
        Files.write(f, Files.readString(f).getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));
        TableException e = assertThrows(TableException.class, () -> Tables.load(TableSource.directory(dir)));
        assertEquals(f.toString(), e.path());
        assertEquals(lineOf("errors.csv", "1,"), e.diagnostic().span().line());
        assertEquals("1,error,expecting a preparatory function number after G,Esperando n".length() + 1,
                e.diagnostic().span().column());
        assertEquals("byte 0xFA is not UTF-8: save the file as UTF-8", e.english());
    }

    static Path copyOfTables() throws IOException {
        Path dir = Files.createTempDirectory("gcnc-tables");
        try (Stream<Path> s = Files.list(Path.of("tables"))) {
            for (Path p : (Iterable<Path>) s::iterator) {
                if (Files.isRegularFile(p)) {
                    Files.copy(p, dir.resolve(p.getFileName()), StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
        return dir;
    }
}
