package gcnc;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * The part programs in a folder, as every front end finds them (the command line given a folder,
 * the Gradle plugin's default program tree, the JUnit fixtures' {@code everyProgramIn}): every
 * regular file below it, sub-folders too, whose name ends in one of the extensions, in any case
 * ({@code BROKEN.NC} is a program), in name order. One list for all of them: {@link #EXTENSIONS}
 * unless the front end is told otherwise ({@code --extensions}, {@code gcnc { extensions }}, which
 * the plugin hands to the shop's tests as the system property {@link #PROPERTY}). What a folder
 * holds besides programs is counted by extension, so that a front end can say what it skipped.
 */
public final class ProgramFiles {
    /**
     * The file names a shop's part programs have unless told otherwise (docs/command-line.md):
     * .nc (Fusion 360's Haas and Fanuc turning posts, Mastercam's; most of the reference corpus),
     * .ngc (LinuxCNC), .tap (Fanuc-style posts of Mach3 and Vectric) and .gcode (hobby and
     * maker-shop CAM). Not .txt (a folder's notes would fail as programs) nor .cnc: a shop that
     * saves programs so adds them.
     */
    public static final List<String> EXTENSIONS = List.of("nc", "ngc", "tap", "gcode");

    /** The system property that carries a build's list into its tests: {@code nc,ngc,tap}. */
    public static final String PROPERTY = "gcnc.extensions";

    /** The list in force: {@link #PROPERTY} when set (the Gradle plugin sets it for a shop's tests), else {@link #EXTENSIONS}. */
    public static List<String> configured() {
        String p = System.getProperty(PROPERTY);
        if (p == null || p.isBlank()) {
            return EXTENSIONS;
        }
        return normal(java.util.Arrays.stream(p.split(",")).map(String::trim).filter(e -> !e.isEmpty()).toList());
    }

    /**
     * What a folder holds: its programs, in name order, and the other files it passed over by
     * extension ("txt" -> 2; "" for files without one), hidden files (a leading dot) not counted.
     */
    public record Scan(List<Path> programs, java.util.SortedMap<String, Integer> skipped) {
        public int skippedCount() {
            return skipped.values().stream().mapToInt(Integer::intValue).sum();
        }
    }

    /** The programs below {@code folder} and what else is there ({@link Scan}). */
    public static Scan scan(Path folder, List<String> extensions) throws IOException {
        List<String> lower = normal(extensions);
        java.util.SortedMap<String, Integer> skipped = new java.util.TreeMap<>();
        List<Path> programs;
        try (Stream<Path> files = Files.walk(folder)) {
            programs = files.filter(Files::isRegularFile).filter(p -> {
                if (has(p, lower)) {
                    return true;
                }
                String name = p.getFileName().toString();
                if (!name.startsWith(".")) {
                    skipped.merge(extension(name), 1, Integer::sum);
                }
                return false;
            }).sorted().toList();
        } catch (java.io.UncheckedIOException e) {
            throw e.getCause();
        }
        return new Scan(programs, java.util.Collections.unmodifiableSortedMap(skipped));
    }

    /** Whether a file name is a program's by {@code extensions} (any case, with or without the dot). */
    public static boolean isProgram(String fileName, List<String> extensions) {
        return has(Path.of(fileName), normal(extensions));
    }

    /** "txt" for notes.TXT; "" for a name without an extension. */
    private static String extension(String name) {
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(dot + 1).toLowerCase(Locale.ROOT) : "";
    }

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
