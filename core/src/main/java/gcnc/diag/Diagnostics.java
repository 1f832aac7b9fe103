package gcnc.diag;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Collects the findings of one run. One instance per run: there is no global error flag.
 * Memory is bounded whatever the program does: it grows with the number of places that have a
 * finding, never with program length or with how often a loop runs, and no further than the caps.
 *
 * <p>Folding (every stage alike: parser, program flow, checker, backend, simulator): one finding
 * per cause and place. An error or warning with the same code at the same place as one already
 * reported (a block a WHILE loop, a repeat or a cycle's passes run again) is not reported again; it
 * is counted, and the first report gets a note with the count, E680 "the same in 2000 passes of this
 * block". A note that accompanies a folded finding goes with it; any other note is kept once.
 * A warning repeated elsewhere with the same code and the same arguments (the shipped Haas
 * profile's clamped spindle at each S4000; the same word without its point on every line) is
 * folded too: kept once, where it was first found, with E115 "3 later blocks have the same cause
 * (lines 12, 30, 41)"; what it says is the same, so a second report adds nothing but noise.
 *
 * <p>Caps: at most {@link #ERROR_CAP} errors are kept; the first one past it is replaced by E116
 * (once for the run: a later E116 is not repeated) and the rest are counted in {@link #errorCount}
 * but not kept. At most {@link #OTHER_CAP} warnings and notes are kept; past it a note E681 says
 * so, once. (docs/program-flow.md, "Caps and folding".)
 *
 * <p>Placing: a block says where it comes from ({@code RawBlock.origin}); the stage that follows
 * the program's flow, and the one that reads a called program's file, say so here too ({@link
 * #placeIn}): a finding reported without an origin of its own is put there (the program file as
 * written, unless said otherwise). A finding
 * inside a subprogram gets one note per call that led to it (E136), and is reported once even when
 * the subprogram runs again (a repeat or a second call finds the same thing at the same place).
 */
public final class Diagnostics {
    /** The most errors a run keeps (the checker stops there too, E116). */
    public static final int ERROR_CAP = 10_000;
    /** The most warnings and notes a run keeps (E681 past it). */
    public static final int OTHER_CAP = 10_000;

    /** The findings kept, each with how often it was found. */
    private final KeptFindings all = new KeptFindings();
    /** Where each kept error or warning is in {@link #all}, by code, severity, file and place. */
    private final Map<String, Integer> byPlace = new HashMap<>();
    /** Where each kept warning is in {@link #all}, by code, file and arguments (not place): a repeat elsewhere is folded. */
    private final Map<String, Integer> warningByArgs = new HashMap<>();
    /** Notes kept, exactly (code, file, place, text): a note is never repeated. */
    private final Set<String> notes = new HashSet<>();
    /** The last error or warning reported: the index in {@link #all} of it or of the one it was folded into; -1 past a cap. */
    private int last = -1;
    /** Whether the last error or warning was folded into an earlier one or dropped at a cap, and its place. */
    private boolean lastNotKept;
    private Span lastSpan;
    /** Errors found once per place (kept or past the cap), errors kept, warnings and notes kept. */
    private int errors;
    private int keptErrors;
    private int others;
    private boolean errorCapReached;
    private boolean otherCapReached;
    /** The program's waivers, as the parser reads them ({@link #waive}); null until the first. */
    private Waivers waivers;
    /** Findings a waiver accepts (kept: they are reported as waived), and how many of them were errors. */
    private int waived;
    private int waivedErrors;
    /** Shared with {@link #sibling()}s: where the blocks being checked now come from. */
    private final Place place;

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

    /**
     * Keeps a finding: one without an origin of its own is placed where the blocks being checked
     * come from ({@link #placeIn}); one in a called program, placed so or by its maker (a block the
     * nose compensation held until the next, the simulator's), gets its notes of the calls.
     */
    public void report(Diagnostic d) {
        keep(place.origin != null && d.origin() == Origin.UNPLACED ? d.in(place.origin) : d);
    }

    /** Keeps a finding where it is placed, with its notes of the calls when that is in a called program. */
    private void keep(Diagnostic d) {
        if (d.origin().calls().isEmpty()) {
            add(d);
        } else {
            withCalls(d);
        }
    }

    /** A finding in a called program: once per place, with a note per call. */
    private void withCalls(Diagnostic d) {
        Origin o = d.origin();
        if (!add(d)) {
            return; // found before at this place (another pass or call: counted), or past a cap
        }
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

    /** Keeps a finding, or counts it (folded, or past a cap); whether it was kept. */
    private boolean add(Diagnostic d) {
        if (d.severity() == Severity.NOTE) {
            return addNote(d);
        }
        String key = d.code() + "/" + d.severity() + "@" + d.origin().file() + ":" + d.span();
        Integer at = byPlace.get(key);
        lastSpan = d.span();
        if (at != null) {
            all.count(at, 1);
            last = at;
            lastNotKept = true;
            return false;
        }
        if (d.severity() == Severity.WARNING && foldedElsewhere(d)) {
            return false;
        }
        boolean room = d.severity() == Severity.ERROR ? roomForError(d) : roomForOther(d);
        if (d.severity() == Severity.ERROR && (room || d.code() != Code.E116_ERROR_CAP)) {
            errors++; // kept or past the cap; a second E116 is not another error
        }
        if (!room) {
            last = -1;
            lastNotKept = true;
            return false;
        }
        lastNotKept = false;
        last = all.keep(d);
        byPlace.put(key, last);
        if (d.severity() == Severity.WARNING) {
            warningByArgs.putIfAbsent(argsKey(d), last);
        }
        if (d.severity() == Severity.ERROR) {
            keptErrors++;
        } else {
            others++;
        }
        return true;
    }

    private static String argsKey(Diagnostic d) {
        return d.code() + "@" + d.origin().file() + d.args();
    }

    /** A warning already kept at another place with the same code and arguments: counted there (E115), not kept. */
    private boolean foldedElsewhere(Diagnostic d) {
        Integer at = warningByArgs.get(argsKey(d));
        if (at == null) {
            return false;
        }
        all.laterAt(at, d.span().line());
        last = at;
        lastNotKept = true;
        lastSpan = d.span();
        byPlace.put(d.code() + "/" + d.severity() + "@" + d.origin().file() + ":" + d.span(), at);
        return true;
    }

    /**
     * A note: E680 (another collection's count, as the checker's per-block one) adds to the finding
     * before it; one that goes with a finding not kept (at its place) is not kept either; else kept once.
     */
    private boolean addNote(Diagnostic d) {
        if (d.code() == Code.E680_FOLDED) {
            if (last >= 0) {
                all.count(last, Integer.parseInt(d.args().get(0)) - 1);
            }
            return false;
        }
        if (lastNotKept && d.span().equals(lastSpan)) {
            return false;
        }
        if (!notes.add(d.code() + "@" + d.origin().file() + ":" + d.span() + d.args()) || !roomForOther(d)) {
            return false;
        }
        others++;
        all.keep(d);
        return true;
    }

    /** Whether one more error may be kept; the first past the cap becomes E116, and a second E116 is not kept. */
    private boolean roomForError(Diagnostic d) {
        if (d.code() == Code.E116_ERROR_CAP) {
            boolean first = !errorCapReached;
            errorCapReached = true;
            return first;
        }
        if (keptErrors < ERROR_CAP) {
            return true;
        }
        if (!errorCapReached) {
            errorCapReached = true;
            keptErrors++;
            all.keep(new Diagnostic(Code.E116_ERROR_CAP, Severity.ERROR, d.span(), List.of(Integer.toString(ERROR_CAP)),
                    d.origin()));
        }
        return false;
    }

    /** Whether one more warning or note may be kept; the first past the cap becomes E681. */
    private boolean roomForOther(Diagnostic d) {
        if (others < OTHER_CAP) {
            return true;
        }
        if (!otherCapReached) {
            otherCapReached = true;
            all.keep(new Diagnostic(Code.E681_OTHER_CAP, Severity.NOTE, d.span(), List.of(Integer.toString(OTHER_CAP)),
                    d.origin()));
        }
        return false;
    }

    /**
     * Takes over every finding of another part of the run (the simulator's), in its order; one
     * placed in a called program gets its notes here, once per place, as the checker's do; one the other
     * part left unplaced stays so (it is not put where the flow happens to stand at the end).
     */
    public void addAll(Diagnostics other) {
        for (int k = 0; k < other.all.size(); k++) {
            keep(other.all.get(k));
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
        // the counts, the folded repeats and the indexes by place follow the findings that stay
        int[] moved = all.withdraw(which);
        for (Map<String, Integer> index : List.of(byPlace, warningByArgs)) {
            index.replaceAll((key, at) -> moved[at]);
            index.values().removeIf(at -> at < 0);
        }
        last = last >= 0 && last < moved.length ? moved[last] : -1;
    }

    /** The program's waivers: the parser adds each it reads ({@code (GCNC ALLOW E642: reason)}). */
    public Waivers waivers() {
        if (waivers == null) {
            waivers = new Waivers();
        }
        return waivers;
    }

    /**
     * Applies the program's waivers, once, when the run's findings are final (gcnc.Session): a
     * finding a waiver covers is kept as waived and no longer counts as an error or a warning; the
     * simulator's errors are never waived. Then each waiver that could not waive is a warning at
     * it: one that names a code no waiver may take (E674, E677), or one whose code is not found
     * where it applies (E672, E673; in a run that did not translate ({@code translated} false), a
     * waiver of a code only translating finds is not judged). A waived error in a run that
     * translates is an error of its own, E675: gcnc never translated the block it was found in.
     */
    public void waive(boolean translated) {
        if (waivers == null || waivers.isEmpty()) {
            return;
        }
        List<Waivers.Waiver> list = waivers.all();
        boolean[] used = new boolean[list.size()];
        Diagnostic firstError = null;
        for (int k = 0; k < all.size(); k++) {
            Diagnostic d = all.get(k);
            if (d.waived() || Waivers.unwaivable(d.code())) {
                continue;
            }
            for (int w = 0; w < list.size(); w++) {
                if (list.get(w).covers(d)) {
                    used[w] = true;
                    all.set(k, d.waivedFor(list.get(w).reason()));
                    waived++;
                    if (d.severity() == Severity.ERROR) {
                        errors--;
                        keptErrors--;
                        waivedErrors++;
                        firstError = firstError == null ? d : firstError;
                    } else {
                        others--;
                    }
                    break;
                }
            }
        }
        for (int w = 0; w < list.size(); w++) {
            Waivers.Waiver v = list.get(w);
            Origin where = v.file() == null ? Origin.PROGRAM : Origin.file(v.file());
            Code code = null;
            if (Waivers.waiverCode(v.code())) {
                code = Code.E677_WAIVER_OF_WAIVER;
            } else if (Waivers.unwaivable(v.code())) {
                code = Code.E674_WAIVER_NOT_ALLOWED;
            } else if (!used[w] && (translated || !Waivers.compileOnly(v.code()))) {
                code = v.wholeFile() ? Code.E673_WAIVER_FILE_UNUSED : Code.E672_WAIVER_UNUSED;
            }
            if (code != null) {
                List<String> args = code == Code.E672_WAIVER_UNUSED
                        ? List.of(v.code().id(), Integer.toString(v.line())) : List.of(v.code().id());
                add(new Diagnostic(code, Severity.WARNING, v.at(), args, where));
            }
        }
        if (translated && firstError != null && errors == 0) { // with other errors nothing is written anyway
            add(new Diagnostic(Code.E675_WAIVED_ERROR_NOT_TRANSLATED, Severity.ERROR, firstError.span(),
                    List.of(firstError.code().id(), Integer.toString(waivedErrors)), firstError.origin().withoutCalls()));
        }
    }

    /** How many findings a waiver accepts (reported as waived, counted neither as errors nor as warnings). */
    public int waivedCount() {
        return waived;
    }

    /** Forgets every finding (a scratch collection reused block after block). */
    public void clear() {
        if (all.isEmpty() && errors == 0) {
            return;
        }
        all.clear();
        byPlace.clear();
        warningByArgs.clear();
        notes.clear();
        last = -1;
        lastNotKept = false;
        lastSpan = null;
        errors = 0;
        keptErrors = 0;
        others = 0;
        errorCapReached = false;
        otherCapReached = false;
        waived = 0;
        waivedErrors = 0;
    }

    public boolean hasErrors() {
        return errors > 0;
    }

    /** Every error found once per place: those past the cap included, a folded repeat not. */
    public int errorCount() {
        return errors;
    }

    /** Whether the error cap was reached: later errors are only counted (E116). */
    public boolean capped() {
        return errorCapReached;
    }

    /** How many findings are kept (folded repeats and those past a cap not counted). */
    public int size() {
        return all.size();
    }

    /**
     * Every finding kept, sorted by file and position (stable: same position keeps reporting order),
     * each found more than once followed by its count (E680).
     */
    public List<Diagnostic> sorted() {
        return all.sorted();
    }
}
