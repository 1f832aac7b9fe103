package gcnc.diag;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * Collects the findings of one run. One instance per run: there is no global error flag.
 * Memory grows with the number of findings, never with program length.
 */
public final class Diagnostics {
    private final List<Diagnostic> all = new ArrayList<>();
    private int errors;

    public void report(Diagnostic d) {
        all.add(d);
        if (d.severity() == Severity.ERROR) {
            errors++;
        }
    }

    /** Takes over every finding of another part of the run (the simulator's), in its order. */
    public void addAll(Diagnostics other) {
        other.all.forEach(this::report);
    }

    public void error(Code code, Span span, Object... args) {
        report(Diagnostic.error(code, span, args));
    }

    /** Forgets every finding (a scratch collection reused block after block). */
    public void clear() {
        all.clear();
        errors = 0;
    }

    public boolean hasErrors() {
        return errors > 0;
    }

    public int errorCount() {
        return errors;
    }

    public int size() {
        return all.size();
    }

    /** Every finding, sorted by position (stable: same position keeps reporting order). */
    public List<Diagnostic> sorted() {
        List<Diagnostic> copy = new ArrayList<>(all);
        Collections.sort(copy);
        return Collections.unmodifiableList(copy);
    }
}
