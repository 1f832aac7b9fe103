package gcnc.tables;

import gcnc.dmc.DmcReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * tables/galil_conformance.csv for the tests that hold gcnc to it (gcnc.controller.GalilConformanceTest,
 * gcnc.cli.SenderConformanceTest): its rows, and the names a DMC statement uses, by which a row is found
 * (a command's two letters, {@code #} for a label or {@code #CMDERR} for an automatic subroutine,
 * {@code =} for an assignment, an operand by its stem {@code _CS}, a function {@code @INT}, {@code TIME}).
 * Unlike the other tables a field may hold commas, in double quotes (RFC 4180).
 */
public final class GalilConformance {
    public static final Path CSV = Path.of("tables/galil_conformance.csv");
    public static final List<String> COLUMNS = List.of("id", "kind", "name", "manual", "source", "gcnc", "models",
            "status", "review", "probe", "test");

    /** The automatic subroutines of COMALL: a label of one of these names has a row of its own. */
    public static final Set<String> AUTOMATIC = Set.of("AUTO", "AUTOERR", "CMDERR", "COMINT", "FWERR", "ININT", "LIMSWI",
            "MCTIME", "POSERR", "TCPERR", "AMPERR", "SERERR");

    /** One row: its line in the file and its fields by column. */
    public record Row(int line, Map<String, String> fields) {
        public String get(String column) {
            return fields.get(column);
        }
    }

    private GalilConformance() {
    }

    public static List<Row> rows() throws IOException {
        List<Row> rows = new ArrayList<>();
        List<String> lines = Files.readAllLines(CSV);
        boolean header = true;
        for (int i = 0; i < lines.size(); i++) {
            String l = lines.get(i);
            if (l.isBlank() || l.startsWith("#")) {
                continue;
            }
            List<String> f = fields(l);
            if (header) {
                if (!f.equals(COLUMNS)) {
                    throw new IllegalStateException(CSV + ":" + (i + 1) + ": the columns are " + COLUMNS + ", not " + f);
                }
                header = false;
                continue;
            }
            if (f.size() != COLUMNS.size()) {
                throw new IllegalStateException(CSV + ":" + (i + 1) + ": " + f.size() + " fields, not " + COLUMNS.size());
            }
            Map<String, String> m = new LinkedHashMap<>();
            for (int c = 0; c < f.size(); c++) {
                m.put(COLUMNS.get(c), f.get(c));
            }
            rows.add(new Row(i + 1, m));
        }
        return rows;
    }

    /** A line's fields: commas separate them, a field in double quotes may hold commas and "" for a quote. */
    static List<String> fields(String line) {
        List<String> out = new ArrayList<>();
        StringBuilder b = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (quoted) {
                if (c == '"' && i + 1 < line.length() && line.charAt(i + 1) == '"') {
                    b.append('"');
                    i++;
                } else if (c == '"') {
                    quoted = false;
                } else {
                    b.append(c);
                }
            } else if (c == '"' && b.length() == 0) {
                quoted = true;
            } else if (c == ',') {
                out.add(b.toString());
                b.setLength(0);
            } else {
                b.append(c);
            }
        }
        if (quoted) {
            throw new IllegalStateException("a quote is not closed: " + line);
        }
        out.add(b.toString());
        return out;
    }

    /** The names of the rows, as the coverage checks look them up. */
    public static Set<String> names(List<Row> rows) {
        Set<String> out = new LinkedHashSet<>();
        for (Row r : rows) {
            out.add(r.get("name"));
        }
        return out;
    }

    private static final Pattern OPERAND = Pattern.compile("_([A-Z]{2})");
    private static final Pattern FUNCTION = Pattern.compile("@([A-Z]+)\\[");
    private static final Pattern TIME = Pattern.compile("(?<![A-Za-z0-9_])TIME(?![A-Za-z0-9])");

    /** The names the statements of a DMC line use (DmcReader.statements splits it as the controller does). */
    public static Set<String> namesOfLine(String line) {
        Set<String> out = new LinkedHashSet<>();
        for (String st : DmcReader.statements(line)) {
            out.addAll(namesOf(st));
        }
        return out;
    }

    /** The names one statement uses: its command, and the operands and functions in its arguments. */
    public static Set<String> namesOf(String statement) {
        Set<String> out = new LinkedHashSet<>();
        String st = statement.strip();
        if (st.isEmpty() || st.equals("\\")) {
            return out;
        }
        if (st.equals("\u0012\u0016")) {
            out.add("^R^V");
            return out;
        }
        if (st.startsWith("'") || st.equals("NO") || st.startsWith("NO ")) {
            out.add(st.startsWith("'") ? "'" : "NO");
            return out;
        }
        if (st.charAt(0) == '#') {
            String label = st.substring(1);
            out.add(AUTOMATIC.contains(label) ? "#" + label : "#");
            return out;
        }
        String args;
        int eq = st.indexOf('=');
        if (eq > 0 && st.substring(0, eq).matches("[A-Za-z][A-Za-z0-9]{0,7}(\\[.*\\])?")) {
            String target = st.substring(0, eq);
            // KPC=0, OFC=0: an axis form of a command; TOOL=3, gline=4: a variable
            out.add(target.length() == 3 && Character.isUpperCase(target.charAt(0)) && Character.isUpperCase(target.charAt(1))
                    && "ABCDEFGHXYZW".indexOf(target.charAt(2)) >= 0 && !target.equals("TOOL") ? target.substring(0, 2) : "=");
            args = st.substring(eq + 1);
        } else if (st.length() >= 2 && Character.isUpperCase(st.charAt(0)) && Character.isUpperCase(st.charAt(1))) {
            String cmd = st.substring(0, 2);
            if (st.startsWith("ELSE") || st.startsWith("ENDIF")) {
                cmd = "IF";
            }
            out.add(cmd);
            args = st.substring(2);
            if ((cmd.equals("VP") || cmd.equals("CR")) && (args.indexOf('<') >= 0 || args.indexOf('>') >= 0)) {
                out.add("<>");
            }
        } else {
            out.add(st); // not a statement gcnc knows: the check names it as it is
            return out;
        }
        String bare = args.replaceAll("\"[^\"]*\"", "\"\"");
        Matcher m = OPERAND.matcher(bare);
        while (m.find()) {
            out.add("_" + m.group(1));
        }
        m = FUNCTION.matcher(bare);
        while (m.find()) {
            out.add("@" + m.group(1));
        }
        if (TIME.matcher(bare).find()) {
            out.add("TIME");
        }
        return out;
    }
}
