package gcnc.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Opens part programs, each read once from start to end, so a pipe, a named pipe or standard
 * input ({@code -}) works like a file. Bytes that are not UTF-8 become U+FFFD, which the lexer
 * reports (error 3).
 */
final class SourceFiles {
    /** The name that stands for standard input, as in most Unix tools; a file named "-" is "./-". */
    static final String STDIN = "-";

    private SourceFiles() {
    }

    static boolean isStdin(Path file) {
        return file.toString().equals(STDIN);
    }

    /**
     * Whether an output path is this process's standard output under another name: {@code -},
     * {@code /dev/stdout}, {@code /dev/fd/1}, or the very file standard output is redirected to
     * ({@code gcnc compile p.nc -o log > log}). Then standard output carries the program and the
     * summaries go to standard error, as for {@code -o -}.
     */
    static boolean isStandardOutput(Path output) {
        if (isStdin(output)) {
            return true;
        }
        Path stdout = Path.of("/proc/self/fd/1");
        try {
            return Files.exists(output) && Files.exists(stdout) && Files.isSameFile(output, stdout);
        } catch (java.io.IOException | SecurityException e) {
            return false; // cannot tell: the summary stays where it was
        }
    }

    /** The program's file, or null for standard input (which has none to compare outputs with). */
    static Path fileOf(Path file) {
        return isStdin(file) ? null : file;
    }

    /** How messages name the program: its path as given, or {@code <stdin>} as GCC does. */
    static String display(Path file) {
        return isStdin(file) ? "<stdin>" : file.toString();
    }

    static Reader open(Path file, InputStream stdin) throws IOException {
        return reader(isStdin(file) ? stdin : Files.newInputStream(file));
    }

    static Reader open(Path file) throws IOException {
        return reader(Files.newInputStream(file));
    }

    private static Reader reader(InputStream in) {
        return gcnc.Session.decode(in);
    }

    /** The folder of a program file, where the programs it calls are looked for ("" for a bare file name). */
    static Path folder(Path file) {
        Path parent = file.getParent();
        return parent != null ? parent : Path.of("");
    }

    /** Where the programs a program calls (M98) are looked for: beside it; none for standard input. */
    static java.util.Optional<Path> programsFolder(Path file) {
        return isStdin(file) ? java.util.Optional.empty() : java.util.Optional.of(folder(file));
    }

    /**
     * The short reason an I/O exception gives, without Java's class names, in {@code lang}: the
     * reason E500 gives ({@link gcnc.diag.Phrase#reason}), for the lines that are not a finding.
     */
    static String reason(IOException e, gcnc.tables.ErrorMessages.Lang lang) {
        return gcnc.tables.Tables.builtIn().messages().arguments(java.util.List.of(gcnc.diag.Phrase.reason(e)), lang)
                .get(0);
    }
}
