package gcnc.output;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;

/**
 * Saves one tool offset's wear into the file that keeps it (an offsets file, or the machine
 * profile itself): only the {@code wear.N} line changes, its key, spacing and trailing comment
 * kept, or a new line is appended; every other line, comment and line ending stays as it was. The
 * file is written whole or not at all ({@link AtomicOutput}: a temporary file beside it renamed
 * over it), so a killed run or a full disk never leaves a half-written table. The file is the one
 * the user named ({@code --offsets FILE}, the profile's {@code offsets.file}, {@code --machine
 * FILE}); a symbolic link named so is followed to its file, as an editor would; anything but a
 * regular file (a directory, a device, a pipe) is refused.
 */
public final class WearLines {
    private WearLines() {
    }

    /** {@code text} with offset {@code n}'s wear line set to {@code value} ("0.03, 0"), or that line appended. */
    public static String with(String text, int n, String value) {
        String newline = text.contains("\r\n") ? "\r\n" : "\n";
        String[] lines = text.split("\r?\n", -1);
        StringBuilder out = new StringBuilder();
        boolean done = false;
        for (int i = 0; i < lines.length; i++) {
            String l = lines[i];
            if (!done && isWearLine(l, n)) {
                l = replaced(l, value);
                done = true;
            }
            out.append(l);
            if (i < lines.length - 1) {
                out.append(newline);
            }
        }
        if (!done) {
            if (out.length() > 0 && !text.endsWith("\n")) {
                out.append(newline);
            }
            out.append("wear.").append(n).append(" = ").append(value).append(newline);
        }
        return out.toString();
    }

    /** Whether {@code line} is {@code wear.N = ...} for offset {@code n} (wear.1 and wear.01 alike). */
    static boolean isWearLine(String line, int n) {
        int hash = line.indexOf('#');
        String l = hash >= 0 ? line.substring(0, hash) : line;
        int eq = l.indexOf('=');
        if (eq < 0) {
            return false;
        }
        String key = l.substring(0, eq).trim();
        return key.matches("wear\\.[0-9]{1,2}") && Integer.parseInt(key.substring(5)) == n;
    }

    /** The line with its value replaced: the key and the spacing around the value and the comment kept. */
    private static String replaced(String line, String value) {
        int hash = line.indexOf('#');
        String body = hash >= 0 ? line.substring(0, hash) : line;
        String comment = hash >= 0 ? line.substring(hash) : "";
        int eq = body.indexOf('=');
        String after = body.substring(eq + 1);
        String lead = after.substring(0, after.length() - after.stripLeading().length());
        String trail = after.stripLeading().isEmpty() ? "" : after.substring(after.stripTrailing().length());
        if (lead.isEmpty()) {
            lead = " ";
        }
        if (!comment.isEmpty() && trail.isEmpty()) {
            trail = " ";
        }
        return body.substring(0, eq + 1) + lead + value + trail + comment;
    }

    /**
     * Writes offset {@code n}'s wear {@code value} into {@code file} (made when it does not exist
     * yet), atomically; refuses anything but a regular file.
     */
    public static void save(Path file, int n, String value) throws IOException {
        String text = "";
        if (Files.exists(file)) {
            if (!Files.isRegularFile(file)) {
                throw new java.nio.file.FileSystemException(file.toString(), null,
                        "not a regular file (a directory, a device or a pipe): the wear is kept in a regular file only");
            }
            text = Files.readString(file, StandardCharsets.UTF_8);
        } else if (Files.isSymbolicLink(file) || Files.exists(file, LinkOption.NOFOLLOW_LINKS)) {
            // a dangling link: writing would make a file wherever it points
            throw new java.nio.file.FileSystemException(file.toString(), null,
                    "a symbolic link to nothing: gcnc does not make a file where it points");
        }
        try (AtomicOutput out = new AtomicOutput(file)) {
            out.writer().write(with(text, n, value));
            out.commit();
        }
    }
}
