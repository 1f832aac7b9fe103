package gcnc.gradle;

import gcnc.diag.Finding;
import gcnc.diag.Severity;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The report a person opens when a gcnc task fails: one self-contained HTML page (no script, no
 * external style) with, for each program that has findings, each finding's line and column,
 * severity, code and message beside the program's own line, and the programs that are clean.
 * The JSON and SARIF reports are for tools; this one is what the failure message links to.
 */
final class HtmlReport {
    private HtmlReport() {
    }

    static void write(Path out, String task, String version, List<GcncTask.Program> programs, List<Finding> sorted)
            throws IOException {
        Map<String, List<Finding>> byFile = new LinkedHashMap<>();
        for (Finding f : sorted) {
            byFile.computeIfAbsent(f.file(), k -> new ArrayList<>()).add(f);
        }
        long errors = sorted.stream().filter(f -> f.diagnostic().severity() == Severity.ERROR && !f.diagnostic().waived()).count();
        long waived = sorted.stream().filter(f -> f.diagnostic().waived()).count();
        Files.createDirectories(out.getParent());
        // a name the plugin chose in the build folder: never written through a link planted there (E510)
        gcnc.output.AtomicOutput.write(out, gcnc.output.AtomicOutput.Name.DERIVED, w -> {
            w.write("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>gcnc " + esc(task)
                    + "</title>\n<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}"
                    + "td,th{border:1px solid #ccc;padding:2px 8px;text-align:left;vertical-align:top}"
                    + "code{font-family:monospace;white-space:pre}.error{color:#b00}.warning{color:#a60}.waived{color:#666}</style></head>\n<body>\n");
            w.write("<h1>gcnc " + esc(task) + "</h1>\n<p>" + GcncTask.plural(programs.size(), "program") + ", "
                    + GcncTask.plural(errors, "error") + ", " + GcncTask.plural(sorted.size() - errors - waived, "warning")
                    + (waived == 0 ? "" : ", " + waived + " waived") + " (gcnc " + esc(version) + ")</p>\n");
            for (GcncTask.Program p : programs) {
                List<Finding> found = byFile.get(p.shown());
                if (found == null) {
                    continue;
                }
                List<String> lines = lines(p.file().toPath());
                w.write("<h2><code>" + esc(p.shown()) + "</code></h2>\n<table>\n"
                        + "<tr><th>line:col</th><th>severity</th><th>code</th><th>message</th><th>the program's line</th></tr>\n");
                for (Finding f : found) {
                    int line = f.diagnostic().span().line();
                    String sev = f.diagnostic().waived() ? "waived"
                            : f.diagnostic().severity() == Severity.ERROR ? "error" : "warning";
                    String text = line >= 1 && line <= lines.size() ? lines.get(line - 1) : "";
                    w.write("<tr><td>" + line + ":" + f.diagnostic().span().column() + "</td><td class=\"" + sev + "\">"
                            + sev + "</td><td>" + esc(f.diagnostic().code().id()) + "</td><td>"
                            + (f.diagnostic().waived() ? "waived: " + esc(f.diagnostic().waiver()) + ": " : "") + esc(f.message())
                            + "</td><td><code>" + esc(text) + "</code></td></tr>\n");
                }
                w.write("</table>\n");
            }
            List<String> clean = programs.stream().map(GcncTask.Program::shown).filter(s -> !byFile.containsKey(s)).toList();
            if (!clean.isEmpty()) {
                w.write("<h2>Clean</h2>\n<ul>\n");
                for (String s : clean) {
                    w.write("<li><code>" + esc(s) + "</code></li>\n");
                }
                w.write("</ul>\n");
            }
            w.write("</body></html>\n");
        });
    }

    /** The program's lines as gcnc reads them; none when it cannot be read (its finding says why). */
    private static List<String> lines(Path file) {
        try (java.io.BufferedReader r = new java.io.BufferedReader(gcnc.Session.decode(Files.newInputStream(file)))) {
            return r.lines().toList();
        } catch (IOException | java.io.UncheckedIOException e) {
            return List.of();
        }
    }

    static String esc(String s) {
        StringBuilder b = new StringBuilder(s.length());
        for (char c : s.toCharArray()) {
            switch (c) {
                case '<' -> b.append("&lt;");
                case '>' -> b.append("&gt;");
                case '&' -> b.append("&amp;");
                case '"' -> b.append("&quot;");
                default -> b.append(c);
            }
        }
        return b.toString();
    }
}
