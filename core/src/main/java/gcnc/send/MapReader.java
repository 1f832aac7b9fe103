package gcnc.send;

import java.io.BufferedReader;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Reads a DMC's source map ({@code <out>.dmc.map}, docs/dmc-format.md) tolerantly: an entry is a
 * line whose first word is the DMC line number and whose last whole number is the G-code line;
 * a word between them that is not a number names the file the block came from (the file column
 * being added for called programs; a {@code file:line} word is read as both). Comment lines
 * ({@code #}) and anything else are skipped, so a map with more columns reads the same. A run that
 * starts inside a packed line is written {@code <dmc line>.<k>} (its k-th command, from 0).
 */
public final class MapReader {
    /**
     * The map: for a DMC line (1-based) and a command on it (0-based), the G-code line and file of
     * the run it is in; {@code starts} are the runs' places as {@code line << 16 | command}.
     */
    public record Map(long[] starts, int[] lines, String[] files) {
        /** The G-code line of the DMC line's first command. */
        public int line(int dmcLine) {
            return line(dmcLine, 0);
        }

        public int line(int dmcLine, int statement) {
            int r = run(dmcLine, statement);
            return r < 0 ? 0 : lines[r];
        }

        /** The file of a called program's block, or null for the program itself. */
        public String file(int dmcLine) {
            return file(dmcLine, 0);
        }

        public String file(int dmcLine, int statement) {
            int r = run(dmcLine, statement);
            return r < 0 ? null : files[r];
        }

        private int run(int dmcLine, int statement) {
            int i = Arrays.binarySearch(starts, gcnc.dmc.SourceMap.key(dmcLine, statement));
            return i >= 0 ? i : -i - 2;
        }
    }

    private MapReader() {
    }

    public static Map read(BufferedReader in) throws IOException {
        List<long[]> runs = new ArrayList<>();
        List<String> files = new ArrayList<>();
        for (String l = in.readLine(); l != null; l = in.readLine()) {
            String t = l.strip();
            if (t.isEmpty() || t.startsWith("#")) {
                continue;
            }
            String[] w = t.split("\\s+");
            long place = gcnc.dmc.SourceMap.place(w[0]);
            if (w.length < 2 || place < 0) {
                continue;
            }
            Integer source = null;
            String file = null;
            for (int i = w.length - 1; i >= 1; i--) {
                String word = w[i];
                int colon = word.lastIndexOf(':');
                if (source == null && whole(word)) {
                    source = Integer.parseInt(word);
                } else if (source == null && colon > 0 && whole(word.substring(colon + 1))) {
                    source = Integer.parseInt(word.substring(colon + 1));
                    file = word.substring(0, colon);
                } else if (file == null && !whole(word)) {
                    file = word;
                }
            }
            if (source == null) {
                continue;
            }
            runs.add(new long[] {place, source});
            files.add(file);
        }
        long[] starts = new long[runs.size()];
        int[] lines = new int[runs.size()];
        for (int i = 0; i < starts.length; i++) {
            starts[i] = runs.get(i)[0];
            lines[i] = (int) runs.get(i)[1];
        }
        return new Map(starts, lines, files.toArray(new String[0]));
    }

    private static boolean whole(String s) {
        return !s.isEmpty() && s.length() < 10 && s.chars().allMatch(c -> c >= '0' && c <= '9');
    }
}
