package gcnc.diag;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Collects the findings of one run. One instance per run: there is no global error flag.
 * Memory grows with the number of findings, never with program length.
 *
 * <p>Placing: the stage that follows the program's flow says where the blocks it hands on come
 * from ({@link #placeIn}); a finding reported without an origin of its own is put there (the
 * program file as written, unless said otherwise). A finding
 * inside a subprogram gets one note per call that led to it (E136), and is reported once even when
 * the subprogram runs again (a repeat or a second call finds the same thing at the same place).
 */
public final class Diagnostics {
    private final List<Diagnostic> all = new ArrayList<>();
    private int errors;
    /** Shared with {@link #sibling()}s: where the blocks being checked now come from. */
    private final Place place;
    /** Placed findings inside subprograms already reported (code, file, span, text). */
    private final Set<String> placed = new HashSet<>();

    /** Null until the first {@link #placeIn}: a collection no stage places (a scratch one) keeps findings as made. */
    private static final class Place {
        Origin origin;
    }

    public Diagnostics() {
        this(new Place());
    }

    private Diagnostics(Place place) {
        this.place = place;
    }

    /** A separate collection that places findings where this one does (a second checker on the same blocks). */
    public Diagnostics sibling() {
        return new Diagnostics(place);
    }

    /** From now on, findings reported without an origin of their own belong to {@code origin}. */
    public void placeIn(Origin origin) {
        place.origin = java.util.Objects.requireNonNull(origin);
    }

    /** Where findings reported without an origin of their own are put now (the program file if nobody said). */
    public Origin place() {
        return place.origin == null ? Origin.PROGRAM : place.origin;
    }

    public void report(Diagnostic d) {
        Origin o = place.origin;
        if (o != null && d.origin() == Origin.UNPLACED) {
            d = d.in(o);
            if (!o.calls().isEmpty()) {
                withCalls(d);
                return;
            }
        }
        add(d);
    }

    /** A finding in a called program: once per place, with a note per call. */
    private void withCalls(Diagnostic d) {
        Origin o = d.origin();
        if (!placed.add(d.code() + "@" + o.file() + ":" + d.span() + d.args())) {
            return;
        }
        add(d);
        if (d.severity() != Severity.NOTE) {
            for (Origin.Call c : o.calls()) {
                add(calledFrom(c, d.span(), o.withoutCalls()));
            }
        }
    }

    /**
     * The note for one call (at the finding): E136 when the call and the finding are both in the
     * program file, else it names the file of the call (E144, or E145 for the program file).
     */
    private static Diagnostic calledFrom(Origin.Call c, Span at, Origin where) {
        List<String> args = List.of(c.program(), Integer.toString(c.line()), c.words());
        Code code = Code.E136_CALLED_FROM;
        if (c.file() != null) {
            code = Code.E144_CALLED_FROM_FILE;
            args = List.of(c.program(), Integer.toString(c.line()), c.words(), c.file());
        } else if (where.file() != null) {
            code = Code.E145_CALLED_FROM_PROGRAM_FILE;
        }
        return new Diagnostic(code, Severity.NOTE, at, args, where);
    }

    private void add(Diagnostic d) {
        all.add(d);
        if (d.severity() == Severity.ERROR) {
            errors++;
        }
    }

    /**
     * Takes over every finding of another part of the run (the simulator's), in its order; one
     * placed in a called program gets its notes here, once per place, as the checker's do.
     */
    public void addAll(Diagnostics other) {
        for (Diagnostic d : other.all) {
            if (d.origin() != Origin.UNPLACED && !d.origin().calls().isEmpty()) {
                withCalls(d);
            } else {
                report(d);
            }
        }
    }

    public void error(Code code, Span span, Object... args) {
        report(Diagnostic.error(code, span, args));
    }

    /**
     * Takes back the warnings and notes {@code which} selects: a later stage settled what they left
     * open (the simulation judged the feeds check could not, E660/E661). Errors are never taken back.
     */
    public void withdraw(java.util.function.Predicate<Diagnostic> which) {
        all.removeIf(d -> d.severity() != Severity.ERROR && which.test(d));
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

    /** Every finding, sorted by file and position (stable: same position keeps reporting order). */
    public List<Diagnostic> sorted() {
        List<Diagnostic> copy = new ArrayList<>(all);
        Collections.sort(copy);
        return Collections.unmodifiableList(copy);
    }
}
