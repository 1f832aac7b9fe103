package gcnc.gradle;

import gcnc.diag.Diagnostic;
import gcnc.diag.Origin;
import java.util.List;

/**
 * What a task made of one program, as it is kept between runs (a result file of {@link ResultStore}):
 * its findings in the order they are reported, the files beside it that its calls looked for
 * ({@code M98 P1000}: {@code O1000.nc}, {@code 1000.nc}, found or not), and the task's own lines about
 * it (gcncSimulate's line of summary.txt). Every path in it is relative to the root project, as the
 * reports name programs, so a result restored from the build cache into another clone says the same.
 */
record Outcome(List<Diagnostic> diagnostics, List<String> calls, List<String> extra) {
    Outcome {
        diagnostics = List.copyOf(diagnostics);
        calls = List.copyOf(calls);
        extra = List.copyOf(extra);
    }

    /** The same findings with each file named by {@code shown} (a called program's path, absolute as gcnc read it). */
    static List<Diagnostic> relocated(List<Diagnostic> all, java.util.function.UnaryOperator<String> shown) {
        return all.stream().map(d -> d.origin().file() == null && d.origin().calls().stream().allMatch(c -> c.file() == null)
                ? d : d.in(new Origin(d.origin().file() == null ? null : shown.apply(d.origin().file()),
                        d.origin().calls().stream().map(c -> new Origin.Call(c.program(), c.line(), c.words(),
                                c.file() == null ? null : shown.apply(c.file()))).toList()))).toList();
    }
}
