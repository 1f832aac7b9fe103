package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Walks tables/syntax_actions.csv and tables/block_checks.csv: every row's class carries its number
 * in its name and is the one its registry (SyntaxActions, BlockChecks) pairs with that number, every
 * listed code exists, and the row has its test method (saNN, ebNN).
 */
class TablesWalkTest {
    private static List<String[]> rows(String file) throws IOException {
        List<String[]> out = new ArrayList<>();
        boolean header = true;
        for (String l : Files.readAllLines(Path.of("tables", file))) {
            if (l.isBlank() || l.startsWith("#")) {
                continue;
            }
            if (header) {
                header = false;
                continue;
            }
            out.add(l.split(",", -1));
        }
        return out;
    }

    @Test
    void syntaxActionsAreAllImplementedAndTested() throws Exception {
        List<String[]> rows = rows("syntax_actions.csv");
        assertEquals(15, rows.size());
        for (int i = 0; i < rows.size(); i++) {
            String[] r = rows.get(i);
            int n = Integer.parseInt(r[0]);
            assertEquals(i + 1, n);
            assertTrue(r[1].startsWith(String.format("Sa%02d", n)), r[1] + " does not carry its number");
            assertEquals(r[1], new gcnc.check.action.SyntaxActions().action(n).getClass().getSimpleName(), "action " + n);
            codes(r[3]);
            SyntaxActionsTest.class.getDeclaredMethod(String.format("sa%02d", n));
        }
    }

    @Test
    void blockChecksAreAllImplementedOrderedAndTested() throws Exception {
        List<String[]> rows = rows("block_checks.csv");
        assertEquals(8, rows.size());
        for (int i = 0; i < rows.size(); i++) {
            String[] r = rows.get(i);
            int n = Integer.parseInt(r[0]);
            assertEquals(i + 1, n);
            assertTrue(r[1].startsWith(String.format("Eb%02d", n)), r[1] + " does not carry its number");
            assertEquals(r[1], gcnc.check.block.BlockChecks.check(n).getClass().getSimpleName(), "operation " + n);
            codes(r[3]);
            BlockChecksTest.class.getDeclaredMethod(String.format("eb%02d", n));
            boolean listed = false;
            for (gcnc.check.block.BlockCheck b : gcnc.check.block.BlockChecks.ORDER) {
                listed |= b.getClass().getSimpleName().equals(r[1]);
            }
            assertTrue(listed, r[1] + " is not in BlockChecks.ORDER");
        }
    }

    private static void codes(String field) {
        for (String c : field.trim().split(" ")) {
            if (!c.isEmpty()) {
                Code.byNumber(Integer.parseInt(c));
            }
        }
    }
}
