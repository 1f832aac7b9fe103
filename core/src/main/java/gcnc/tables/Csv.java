package gcnc.tables;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Phrase;
import gcnc.diag.Span;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalDouble;

/**
 * The small CSV dialect of tables/: '#' starts a comment line, the first other line names the
 * columns, fields are separated by commas (no quoting; texts hold no commas). Every field keeps
 * its line and column so a bad value is reported where it is.
 */
public final class Csv {
    private final String path;
    private final List<String> header;
    private final List<Row> rows;

    /** One data row; {@link #get}, {@link #integer} and {@link #decimal} report faults in place. */
    public final class Row {
        private final int line;
        private final String[] fields;
        private final int[] columns;

        Row(int line, String[] fields, int[] columns) {
            this.line = line;
            this.fields = fields;
            this.columns = columns;
        }

        public int line() {
            return line;
        }

        public String get(String column) throws TableException {
            int i = header.indexOf(column);
            if (i < 0) {
                throw fault(path, 1, 1, Phrase.CSV_MISSING_COLUMN.with(column));
            }
            if (i >= fields.length) {
                throw fault(path, line, 1, Phrase.CSV_MISSING_VALUE.with(column));
            }
            return fields[i].trim();
        }

        public int integer(String column) throws TableException {
            String v = get(column);
            try {
                return Integer.parseInt(v);
            } catch (NumberFormatException e) {
                throw fault(path, line, columns[header.indexOf(column)], Phrase.CSV_NOT_WHOLE.with(v, column));
            }
        }

        /** A finite decimal number ({@link Decimal}): NaN and infinities are faults like any other text. */
        public double decimal(String column) throws TableException {
            String v = get(column);
            OptionalDouble d = Decimal.parse(v);
            if (d.isEmpty()) {
                throw fault(path, line, columns[header.indexOf(column)], Phrase.NOT_A_NUMBER.with(v, column));
            }
            return d.getAsDouble();
        }

        /** Reports a fault in this row's given column (for range and consistency checks). */
        public TableException faultAt(String column, String message) {
            int i = header.indexOf(column);
            return fault(path, line, i < 0 || i >= columns.length ? 1 : columns[i], message);
        }

        /**
         * Reports a fault {@code offset} characters into the value of a column as {@link #get} returns
         * it (trimmed), so that a fault inside a long text points at the character itself.
         */
        public TableException faultAt(String column, int offset, String message) {
            int i = header.indexOf(column);
            if (i < 0 || i >= columns.length) {
                return faultAt(column, message);
            }
            String raw = fields[i];
            int lead = 0;
            while (lead < raw.length() && raw.charAt(lead) <= ' ') {
                lead++;
            }
            return fault(path, line, columns[i] + lead + offset, message);
        }
    }

    private Csv(String path, List<String> header, List<Row> rows) {
        this.path = path;
        this.header = header;
        this.rows = rows;
    }

    public static Csv parse(String path, String text) throws TableException {
        List<String> header = null;
        List<Row> rows = new ArrayList<>();
        Csv csv = null;
        // lines end at \n, a \r before it dropped (as split("\r?\n") would, without a regular expression)
        int n = -1;
        for (int at = 0; at <= text.length(); ) {
            n++;
            int nl = text.indexOf('\n', at);
            int end = nl < 0 ? text.length() : nl;
            String l = text.substring(at, nl >= 0 && end > at && text.charAt(end - 1) == '\r' ? end - 1 : end);
            at = nl < 0 ? text.length() + 1 : nl + 1;
            if (l.isBlank() || l.stripLeading().startsWith("#")) {
                continue;
            }
            String[] fields = l.split(",", -1);
            int[] cols = new int[fields.length];
            int c = 1;
            for (int i = 0; i < fields.length; i++) {
                cols[i] = c;
                c += fields[i].length() + 1;
            }
            if (header == null) {
                header = new ArrayList<>();
                for (String f : fields) {
                    header.add(f.trim());
                }
                csv = new Csv(path, List.copyOf(header), rows);
            } else {
                if (fields.length != header.size()) {
                    throw fault(path, n + 1, 1, Phrase.CSV_FIELD_COUNT.with(header.size(), fields.length));
                }
                rows.add(csv.new Row(n + 1, fields, cols));
            }
        }
        if (csv == null) {
            throw fault(path, 1, 1, Phrase.CSV_EMPTY.arg());
        }
        return csv;
    }

    public List<Row> rows() {
        return rows;
    }

    public String path() {
        return path;
    }

    static TableException fault(String path, int line, int column, String message) {
        return new TableException(path, Diagnostic.error(Code.E400_TABLE, Span.of(line, column), message));
    }
}
