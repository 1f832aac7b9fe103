package gcnc.controller;

import gcnc.tables.Csv;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import java.util.HashMap;
import java.util.Map;

/**
 * Where the controller takes a command: tables/galil_terminal.csv, the reference's "Not Valid in
 * terminal" and "Not Valid in program" flags of the commands gcnc uses. A command the table marks is
 * refused as Galil refuses it (COMALL TC): from the host with TC 2 "Command only valid from program",
 * from a thread with TC 3 "Command not valid in program". A command the table does not list is valid in both.
 */
final class CommandRules {
    /** Where a command is valid. */
    private record Where(boolean terminal, boolean program) {
    }

    private static final Map<String, Where> RULES = load();

    private CommandRules() {
    }

    private static Map<String, Where> load() {
        try {
            String name = "galil_terminal.csv";
            TableSource t = TableSource.builtIn();
            Map<String, Where> m = new HashMap<>();
            for (Csv.Row r : Csv.parse(t.describe(name), t.read(name)).rows()) {
                m.put(r.get("command"), new Where(yes(r.get("terminal")), yes(r.get("program"))));
            }
            return Map.copyOf(m);
        } catch (TableException e) {
            throw new IllegalStateException("the tables built into gcnc.jar are broken: " + e.getMessage(), e);
        }
    }

    private static boolean yes(String cell) {
        if (!cell.equals("yes") && !cell.equals("no")) {
            throw new IllegalStateException("galil_terminal.csv: '" + cell + "' where yes or no belongs");
        }
        return cell.equals("yes");
    }

    /** The command a statement is, as the table names it: label, IF, ELSE, ENDIF, ^R^V, or its two letters. */
    static String head(String st) {
        if (st.startsWith("#")) {
            return "label";
        }
        if (st.equals("\u0012\u0016")) {
            return "^R^V";
        }
        for (String w : new String[] {"ENDIF", "ELSE", "IF"}) {
            if (Statements.word(st, w)) {
                return w;
            }
        }
        return st.length() >= 2 ? st.substring(0, 2) : st;
    }

    /** Refuses {@code st} where the reference says it is not valid: from the host ({@code th} null) or a thread. */
    static void check(String st, ProgramThread th) throws GalilException {
        Where w = RULES.get(head(st));
        if (w == null) {
            return;
        }
        if (th == null && !w.terminal()) {
            throw new GalilException(Tc.ONLY_IN_PROGRAM);
        }
        if (th != null && !w.program()) {
            throw new GalilException(Tc.NOT_IN_PROGRAM);
        }
    }
}
