package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * No main code dispatches over a sealed hierarchy with an {@code if … else if} chain of type tests
 * (issue 32): a chain takes a new member silently for none of its branches, where a visitor or a switch
 * expression over a kind enum (gcnc.dmc.CommandKind, gcnc.check.MotionKind) does not compile until the
 * member is placed. What it checks, on the sources as text: every {@code else if (…)} whose condition
 * has {@code instanceof X}, with X (its last name: {@code Command.End} is {@code End}) a type that
 * implements or extends a sealed interface of the main sources, is a failure. A single type test
 * ({@code if (c instanceof Command.End)}, with a plain {@code else} or none) is a question about one
 * kind and is not looked at.
 */
class SealedDispatchTest {
    private static final List<String> MODULES = List.of("core", "cli", "controller", "studio", "junit",
            "gradle-plugin", "lsp");

    private static final Pattern SEALED = Pattern.compile("\\bsealed\\s+interface\\s+(\\w+)");

    /** A type's header up to its body: its name, then what it implements or extends. */
    private static final Pattern DECLARATION = Pattern.compile(
            "\\b(?:record|class|interface|enum)\\s+(\\w+)[^{;]*?\\b(?:implements|extends)\\s+([^{]+)\\{");

    private static final Pattern ELSE_IF = Pattern.compile("\\belse\\s+if\\s*\\(");

    private static final Pattern INSTANCEOF = Pattern.compile("\\binstanceof\\s+(?:final\\s+)?([\\w.]+)");

    private static List<Path> mainSources() {
        List<Path> all = new ArrayList<>();
        for (String module : MODULES) {
            try (Stream<Path> s = Files.walk(Path.of(module, "src/main/java"))) {
                s.filter(p -> p.toString().endsWith(".java")).sorted().forEach(all::add);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return all;
    }

    private static String read(Path p) {
        try {
            return Files.readString(p);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The simple names of the types that implement or extend a sealed interface of the main sources. */
    static Set<String> sealedMembers(List<String> sources) {
        Set<String> sealed = new TreeSet<>();
        for (String s : sources) {
            Matcher m = SEALED.matcher(s);
            while (m.find()) {
                sealed.add(m.group(1));
            }
        }
        Set<String> members = new TreeSet<>();
        for (String s : sources) {
            Matcher m = DECLARATION.matcher(s);
            while (m.find()) {
                for (String parent : m.group(2).split("[,\\s]+")) {
                    String last = parent.replaceAll("<.*", "").replaceAll(".*\\.", "");
                    if (sealed.contains(last)) {
                        members.add(m.group(1));
                    }
                }
            }
        }
        return members;
    }

    /** "line n: condition" for each {@code else if} of {@code source} that tests a sealed member's type. */
    static List<String> chains(String source, Set<String> members) {
        List<String> out = new ArrayList<>();
        Matcher m = ELSE_IF.matcher(source);
        while (m.find()) {
            int close = closing(source, m.end());
            String condition = source.substring(m.end(), close);
            Matcher t = INSTANCEOF.matcher(condition);
            while (t.find()) {
                String type = t.group(1).replaceAll(".*\\.", "");
                if (members.contains(type)) {
                    int line = (int) source.substring(0, m.start()).chars().filter(ch -> ch == '\n').count() + 1;
                    out.add("line " + line + ": else if (" + condition.replaceAll("\\s+", " ") + ")");
                    break;
                }
            }
        }
        return out;
    }

    /** The index of the parenthesis that closes the one opened just before {@code from}. */
    private static int closing(String s, int from) {
        int depth = 1;
        for (int i = from; i < s.length(); i++) {
            char c = s.charAt(i);
            depth += c == '(' ? 1 : c == ')' ? -1 : 0;
            if (depth == 0) {
                return i;
            }
        }
        return s.length();
    }

    @Test
    void noElseIfChainTestsTheTypeOfASealedMember() {
        List<Path> files = mainSources();
        List<String> texts = files.stream().map(SealedDispatchTest::read).toList();
        Set<String> members = sealedMembers(texts);
        // the hierarchies the issue names are found: the scan reads the declarations it is meant to
        assertTrue(members.containsAll(Set.of("End", "Label", "InputIs", "Count", "Linear", "Dwell", "Thread")),
                members.toString());
        List<String> found = new ArrayList<>();
        for (int i = 0; i < files.size(); i++) {
            String file = files.get(i).toString().replace('\\', '/');
            chains(texts.get(i), members).forEach(c -> found.add(file + " " + c));
        }
        assertEquals(List.of(), found, "a chain of type tests over a sealed hierarchy: a visitor or an exhaustive"
                + " switch over a kind decides every member");
    }

    @Test
    void theScanFindsAChainAndPassesASingleTest() {
        String source = "sealed interface Shape {}\nrecord Round() implements Shape {}\nrecord Square() implements Shape {}\n"
                + "class Use { void f(Object s) {\n if (s instanceof Round r) { }\n else if (s.hashCode() > 0\n"
                + "   && s instanceof Square) { }\n if (s instanceof Square) { } else { }\n"
                + " if (s instanceof Round) { } else if (s instanceof String) { } } }\n";
        Set<String> members = sealedMembers(List.of(source));
        assertEquals(Set.of("Round", "Square"), members);
        assertEquals(List.of("line 6: else if (s.hashCode() > 0 && s instanceof Square)"), chains(source, members));
    }
}
