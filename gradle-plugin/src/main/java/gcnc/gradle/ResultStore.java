package gcnc.gradle;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Origin;
import gcnc.diag.Severity;
import gcnc.diag.Span;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A task's results kept between runs, in its results folder (an output of the task, so Gradle's
 * build cache stores and restores it with the reports): one result file per program
 * ({@link Outcome}: findings, the files its calls looked for, the task's own lines) under
 * {@code programs/}, and {@code index.tsv}, the call graph: for each program its path, its content's
 * SHA-256 and the files its calls looked for, under the fingerprint of everything else the verdicts
 * depend on (gcnc's classes, the machine, the control, the tables). The next run re-judges a program
 * whose content changed and every program whose calls looked for a file that changed, appeared or
 * went; a different fingerprint, or no index, re-judges them all.
 *
 * <p>Plain text, one record a line, fields separated by tabs and escaped ({@code %09}, {@code %0A},
 * {@code %0D}, {@code %25}; {@code %N} for none): nothing that needs a library, and a file a person can read.
 */
final class ResultStore {
    private static final String INDEX_HEAD = "gcnc-library-index 1";
    private static final String RESULT_HEAD = "gcnc-result 1";

    /** One program of the index: how reports name it, its path under the program tree, its content's hash, what its calls looked for. */
    record Entry(String shown, String relativePath, String hash, List<String> calls) {
    }

    private final Path folder;

    ResultStore(Path folder) {
        this.folder = folder;
    }

    Path folder() {
        return folder;
    }

    /** The index of the last run under {@code fingerprint}; empty when there is none, it is unreadable, or its fingerprint differs. */
    java.util.Optional<Map<String, Entry>> index(String fingerprint) {
        Map<String, Entry> entries = new LinkedHashMap<>();
        try (BufferedReader in = Files.newBufferedReader(folder.resolve("index.tsv"), StandardCharsets.UTF_8)) {
            if (!INDEX_HEAD.equals(in.readLine()) || !("fingerprint\t" + fingerprint).equals(in.readLine())) {
                return java.util.Optional.empty();
            }
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                List<String> f = fields(line);
                if (f.size() < 4 || !"program".equals(f.get(0))) {
                    return java.util.Optional.empty();
                }
                entries.put(f.get(1), new Entry(f.get(1), f.get(2), f.get(3), List.copyOf(f.subList(4, f.size()))));
            }
        } catch (IOException | RuntimeException e) {
            return java.util.Optional.empty(); // no index, or a broken one: every program is judged again
        }
        return java.util.Optional.of(entries);
    }

    /** Removes the index first: a run that stops half-way leaves none, and the next judges every program. */
    void forgetIndex() throws IOException {
        Files.deleteIfExists(folder.resolve("index.tsv"));
    }

    void writeIndex(String fingerprint, List<Entry> entries) throws IOException {
        StringBuilder s = new StringBuilder(INDEX_HEAD).append('\n').append("fingerprint\t").append(fingerprint).append('\n');
        for (Entry e : entries) {
            List<String> f = new ArrayList<>(java.util.Arrays.asList("program", e.shown(), e.relativePath(), e.hash()));
            f.addAll(e.calls());
            s.append(line(f)).append('\n');
        }
        write(folder.resolve("index.tsv"), s.toString());
    }

    /** The kept result of one program. */
    Outcome read(String shown) throws IOException {
        List<Diagnostic> diagnostics = new ArrayList<>();
        List<String> calls = new ArrayList<>();
        List<String> extra = new ArrayList<>();
        try (BufferedReader in = Files.newBufferedReader(resultFile(shown), StandardCharsets.UTF_8)) {
            if (!RESULT_HEAD.equals(in.readLine())) {
                throw new IOException("not a gcnc result file: " + resultFile(shown));
            }
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                List<String> f = fields(line);
                switch (f.get(0)) {
                    case "call" -> calls.add(f.get(1));
                    case "extra" -> extra.add(f.get(1));
                    case "finding" -> diagnostics.add(diagnostic(f));
                    default -> throw new IOException("unknown record " + f.get(0) + " in " + resultFile(shown));
                }
            }
        } catch (RuntimeException e) {
            throw new IOException("broken result file " + resultFile(shown) + ": " + e, e);
        }
        return new Outcome(diagnostics, calls, extra);
    }

    void write(String shown, Outcome o) throws IOException {
        StringBuilder s = new StringBuilder(RESULT_HEAD).append('\n');
        for (String c : o.calls()) {
            s.append(line(List.of("call", c))).append('\n');
        }
        for (String x : o.extra()) {
            s.append(line(List.of("extra", x))).append('\n');
        }
        for (Diagnostic d : o.diagnostics()) {
            List<String> f = new ArrayList<>(List.of("finding", d.code().name(), d.severity().name(),
                    Integer.toString(d.span().line()), Integer.toString(d.span().column()), Integer.toString(d.span().endColumn())));
            f.add(d.waiver());
            f.add(d.origin().file());
            f.add(Integer.toString(d.args().size()));
            f.addAll(d.args());
            for (Origin.Call c : d.origin().calls()) {
                f.addAll(java.util.Arrays.asList(c.program(), Integer.toString(c.line()), c.words(), c.file()));
            }
            s.append(line(f)).append('\n');
        }
        Path file = resultFile(shown);
        Files.createDirectories(file.getParent());
        write(file, s.toString());
    }

    void remove(String shown) throws IOException {
        Files.deleteIfExists(resultFile(shown));
    }

    /** programs/&lt;the program's path as reports name it&gt;.result (an absolute path kept below programs/ too). */
    private Path resultFile(String shown) {
        String relative = shown.replace('\\', '/');
        while (relative.startsWith("/")) {
            relative = relative.substring(1);
        }
        relative = relative.replace("../", "__/");
        return folder.resolve("programs").resolve(relative + ".result");
    }

    /** finding, code, severity, line, column, end column, waiver, origin file, how many arguments, the arguments, then 4 fields a call. */
    private static Diagnostic diagnostic(List<String> f) {
        int args = Integer.parseInt(f.get(8));
        List<Origin.Call> calls = new ArrayList<>();
        for (int k = 9 + args; k + 3 < f.size(); k += 4) {
            calls.add(new Origin.Call(f.get(k), Integer.parseInt(f.get(k + 1)), f.get(k + 2), f.get(k + 3)));
        }
        Origin origin = f.get(7) == null && calls.isEmpty() ? Origin.PROGRAM : new Origin(f.get(7), calls);
        return new Diagnostic(Code.valueOf(f.get(1)), Severity.valueOf(f.get(2)),
                new Span(Integer.parseInt(f.get(3)), Integer.parseInt(f.get(4)), Integer.parseInt(f.get(5))),
                f.subList(9, 9 + args), origin, f.get(6));
    }

    /** The SHA-256 of a file's bytes, in hex. */
    static String hash(Path file) throws IOException {
        if (!Files.isRegularFile(file)) {
            return Files.exists(file) ? "not a file" : "none";
        }
        MessageDigest sha = sha256();
        byte[] buffer = new byte[1 << 14];
        try (InputStream in = Files.newInputStream(file)) {
            for (int n = in.read(buffer); n > 0; n = in.read(buffer)) {
                sha.update(buffer, 0, n);
            }
        } catch (NoSuchFileException e) {
            return "none";
        }
        return HexFormat.of().formatHex(sha.digest());
    }

    /** The SHA-256 of text, in hex. */
    static String hash(String text) {
        return HexFormat.of().formatHex(sha256().digest(text.getBytes(StandardCharsets.UTF_8)));
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }

    private static void write(Path file, String text) throws IOException {
        // names the plugin chose in the build folder: never written through a link planted there (E510)
        gcnc.output.AtomicOutput.write(file, gcnc.output.AtomicOutput.Name.DERIVED, w -> w.write(text));
    }

    private static String line(List<String> fields) {
        StringBuilder s = new StringBuilder();
        for (int k = 0; k < fields.size(); k++) {
            if (k > 0) {
                s.append('\t');
            }
            String f = fields.get(k);
            if (f == null) {
                s.append("%N");
                continue;
            }
            for (int i = 0; i < f.length(); i++) {
                char c = f.charAt(i);
                switch (c) {
                    case '\t' -> s.append("%09");
                    case '\n' -> s.append("%0A");
                    case '\r' -> s.append("%0D");
                    case '%' -> s.append("%25");
                    default -> s.append(c);
                }
            }
        }
        return s.toString();
    }

    private static List<String> fields(String line) {
        List<String> out = new ArrayList<>();
        for (String f : line.split("\t", -1)) {
            if (f.equals("%N")) {
                out.add(null);
                continue;
            }
            StringBuilder s = new StringBuilder(f.length());
            for (int i = 0; i < f.length(); i++) {
                char c = f.charAt(i);
                if (c == '%') {
                    s.append((char) Integer.parseInt(f.substring(i + 1, i + 3), 16));
                    i += 2;
                } else {
                    s.append(c);
                }
            }
            out.add(s.toString());
        }
        return out;
    }
}
