package gcnc.tables;

import gcnc.diag.Phrase;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/**
 * Where table files come from: the copy inside the jar, or a directory the user points at
 * with {@code --tables DIR} (an edited copy, no rebuild needed). Both decode with {@link Utf8}:
 * a byte-order mark is dropped, a byte that is not UTF-8 is a located fault.
 */
public interface TableSource {
    /** The text of the named file, e.g. {@code g_codes.csv} or {@code machines/generic.machine}. */
    String read(String name) throws TableException;

    /** A name to print in diagnostics for the named file. */
    String describe(String name);

    /** The named file read as a table, its faults located under {@link #describe}'s name. */
    default Csv csv(String name) throws TableException {
        return Csv.parse(describe(name), read(name));
    }

    /** The copy inside the jar: its tables are checked when gcnc is built (Tables reads some lazily). */
    default boolean isBuiltIn() {
        return false;
    }

    static TableSource builtIn() {
        return new TableSource() {
            @Override
            public boolean isBuiltIn() {
                return true;
            }

            @Override
            public String read(String name) throws TableException {
                try (InputStream in = TableSource.class.getResourceAsStream("/tables/" + name)) {
                    if (in == null) {
                        throw Csv.fault(describe(name), 1, 1, Phrase.TABLE_NOT_IN_JAR.arg());
                    }
                    return Utf8.decode(describe(name), Utf8.bounded(describe(name), in));
                } catch (IOException e) {
                    throw Csv.fault(describe(name), 1, 1, Phrase.reason(e));
                }
            }

            @Override
            public String describe(String name) {
                return "gcnc.jar!/tables/" + name;
            }
        };
    }

    static TableSource directory(Path dir) {
        return new TableSource() {
            @Override
            public String read(String name) throws TableException {
                Path p = dir.resolve(name);
                try {
                    return Utf8.read(describe(name), p);
                } catch (NoSuchFileException e) {
                    throw Csv.fault(describe(name), 1, 1, Phrase.TABLE_FILE_NOT_FOUND.arg());
                } catch (IOException e) {
                    throw Csv.fault(describe(name), 1, 1, Phrase.reason(e));
                }
            }

            @Override
            public String describe(String name) {
                return dir.resolve(name).toString();
            }
        };
    }
}
