package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * docs/architecture.md against the main sources (issue 32): every type it names exists, every
 * package says its job in a package-info.java, and no two main classes share a simple name.
 */
class ArchitectureDocTest {
    /** The subprojects whose main sources are gcnc's own (picocli17 is picocli's). */
    private static final List<String> MODULES = List.of("core", "cli", "controller", "studio", "junit",
            "gradle-plugin", "lsp");

    private static final Pattern TYPE = Pattern.compile(
            "(?m)^\\s*(?:(?:public|protected|private|static|final|abstract|sealed|non-sealed|strictfp)\\s+)*"
                    + "(?:class|record|interface|enum|@interface)\\s+([A-Z]\\w*)");

    /** A qualified name in the page: a package path, then a type (and maybe a member or nested type). */
    private static final Pattern QUALIFIED = Pattern.compile("\\bgcnc((?:\\.[a-z]\\w*)*)\\.([A-Z]\\w*)((?:\\.[A-Z]\\w*)*)");

    private static final Pattern PACKAGE = Pattern.compile("`gcnc((?:\\.[a-z]\\w*)+)`");

    private static final Pattern CODE_SPAN = Pattern.compile("`([^`]+)`");

    private static final Pattern CAPITALISED = Pattern.compile("(?<![\\w.\"])([A-Z][a-z]\\w*)");

    private static List<Path> mainSources() {
        List<Path> all = new ArrayList<>();
        for (String module : MODULES) {
            Path root = Path.of(module, "src/main/java/gcnc");
            try (Stream<Path> s = Files.walk(root)) {
                s.filter(p -> p.toString().endsWith(".java")).sorted().forEach(all::add);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return all;
    }

    private static String packageOf(Path file) {
        Path rel = file.getParent();
        int i = 0;
        while (!rel.getName(i).toString().equals("java")) {
            i++;
        }
        return rel.subpath(i + 1, rel.getNameCount()).toString().replace('/', '.');
    }

    /** Every type in main code, qualified, nested ones as Outer.Inner's simple names too. */
    private record Types(Set<String> qualified, Set<String> simple, Set<String> packages) {
        static Types read() {
            Set<String> qualified = new TreeSet<>();
            Set<String> simple = new TreeSet<>();
            Set<String> packages = new TreeSet<>();
            for (Path f : mainSources()) {
                String pkg = packageOf(f);
                packages.add(pkg);
                String name = f.getFileName().toString().replace(".java", "");
                if (name.equals("package-info")) {
                    continue;
                }
                qualified.add(pkg + "." + name);
                simple.add(name);
                try {
                    Matcher m = TYPE.matcher(Files.readString(f));
                    while (m.find()) {
                        simple.add(m.group(1));
                        if (!m.group(1).equals(name)) {
                            qualified.add(pkg + "." + name + "." + m.group(1));
                        }
                    }
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            }
            return new Types(qualified, simple, packages);
        }
    }

    private static String page() throws IOException {
        return Files.readString(Path.of("docs/architecture.md"));
    }

    @Test
    void everyQualifiedTypeThePageNamesExists() throws IOException {
        Types types = Types.read();
        Set<String> missing = new TreeSet<>();
        Matcher m = QUALIFIED.matcher(page());
        while (m.find()) {
            String type = "gcnc" + m.group(1) + "." + m.group(2);
            if (!types.qualified().contains(type)) {
                missing.add(type);
            } else if (!m.group(3).isEmpty() && !types.qualified().contains(type + m.group(3))) {
                missing.add(type + m.group(3));
            }
        }
        assertEquals(Set.of(), missing, "docs/architecture.md names types main code does not have");
    }

    @Test
    void everyPackageThePageNamesExists() throws IOException {
        Types types = Types.read();
        Set<String> missing = new TreeSet<>();
        Matcher m = PACKAGE.matcher(page());
        while (m.find()) {
            if (!types.packages().contains("gcnc" + m.group(1))) {
                missing.add("gcnc" + m.group(1));
            }
        }
        assertEquals(Set.of(), missing, "docs/architecture.md names packages main code does not have");
    }

    /** In the contracts table every capitalised name in code is a main type or one of the JDK's. */
    @Test
    void theContractsTableNamesOnlyTypesThatExist() throws IOException {
        Types types = Types.read();
        String page = page();
        int start = page.indexOf("## Contracts between stages");
        assertTrue(start >= 0, "docs/architecture.md has no contracts table");
        int end = page.indexOf("\n## ", start + 1);
        List<String> rows = page.substring(start, end < 0 ? page.length() : end).lines()
                .filter(l -> l.startsWith("| ") && !l.startsWith("| stage")).collect(Collectors.toList());
        assertTrue(rows.size() >= 4, "the contracts table has a row per stage: " + rows);
        Set<String> missing = new TreeSet<>();
        for (String row : rows) {
            Matcher span = CODE_SPAN.matcher(row);
            while (span.find()) {
                Matcher name = CAPITALISED.matcher(span.group(1).replaceAll("\"[^\"]*\"", ""));
                while (name.find()) {
                    String n = name.group(1);
                    if (!types.simple().contains(n) && !jdk(n)) {
                        missing.add(n);
                    }
                }
            }
        }
        assertEquals(Set.of(), missing, "the contracts table names types main code does not have");
    }

    private static boolean jdk(String simpleName) {
        for (String pkg : List.of("java.lang.", "java.util.", "java.util.function.", "java.io.", "java.nio.file.")) {
            try {
                Class.forName(pkg + simpleName, false, ArchitectureDocTest.class.getClassLoader());
                return true;
            } catch (ClassNotFoundException e) {
                // not in this package
            }
        }
        return false;
    }

    @Test
    void everyPackageSaysItsJob() {
        Set<String> without = new TreeSet<>();
        Map<String, Boolean> has = new TreeMap<>();
        for (Path f : mainSources()) {
            has.merge(f.getParent().toString(), f.getFileName().toString().equals("package-info.java"), Boolean::logicalOr);
        }
        has.forEach((dir, yes) -> {
            if (!yes) {
                without.add(dir);
            }
        });
        assertEquals(Set.of(), without, "packages without a package-info.java saying their job");
    }

    @Test
    void noTwoMainClassesShareASimpleName() {
        Map<String, List<String>> byName = new TreeMap<>();
        for (Path f : mainSources()) {
            String name = f.getFileName().toString();
            if (!name.equals("package-info.java")) {
                byName.computeIfAbsent(name.replace(".java", ""), k -> new ArrayList<>()).add(packageOf(f));
            }
        }
        Map<String, List<String>> twice = new TreeMap<>();
        byName.forEach((name, packages) -> {
            if (packages.size() > 1) {
                twice.put(name, packages);
            }
        });
        assertEquals(Map.of(), twice, "simple names defined in more than one package");
    }
}
