package gcnc;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * The part programs in a folder, as every front end finds them (the command line given a folder,
 * the JUnit fixtures' {@code everyProgramIn}): every regular file below it, sub-folders too, whose
 * name ends in one of the extensions, in any case ({@code BROKEN.NC} is a program), in name order.
 */
public final class ProgramFiles {
    /** The file names a shop's part programs have unless told otherwise: .nc, .ngc, .tap. */
    public static final List<String> EXTENSIONS = List.of("nc", "ngc", "tap");

    private ProgramFiles() {
    }

    /** The programs below {@code folder} with one of {@code extensions} ("nc" or ".nc", any case). */
    public static List<Path> in(Path folder, List<String> extensions) throws IOException {
        List<String> lower = normal(extensions);
        try (Stream<Path> files = Files.walk(folder)) {
            return files.filter(Files::isRegularFile).filter(p -> has(p, lower)).sorted().toList();
        } catch (java.io.UncheckedIOException e) {
            throw e.getCause(); // a sub-folder that cannot be read, found while walking: the caller's E500, not a trace
        }
    }

    /** The extensions without a leading dot, in lower case; at least one. */
    public static List<String> normal(List<String> extensions) {
        if (extensions.isEmpty()) {
            throw new IllegalArgumentException("name at least one file extension for the part programs");
        }
        return extensions.stream().map(e -> e.replaceFirst("^\\.", "").toLowerCase(Locale.ROOT)).toList();
    }

    private static boolean has(Path p, List<String> lower) {
        String name = p.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot > 0 && lower.contains(name.substring(dot + 1).toLowerCase(Locale.ROOT));
    }
}
