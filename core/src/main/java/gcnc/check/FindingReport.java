package gcnc.check;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Severity;
import gcnc.ir.RawBlock;
import java.util.EnumMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Reports the checker's findings. One root cause, one error: a prerequisite broken again by later
 * blocks (a program that never starts the spindle) is reported at its first block, with a note
 * that counts the later ones (E115). Findings of contour blocks read ahead are remembered, so that
 * following them again (G70) does not repeat them; what only the other position of the block
 * delete switch found is added with a note saying so (E118).
 */
final class FindingReport {
    /** Prerequisite errors that later blocks repeat until the program fixes the cause. */
    private static final Set<Code> ROOT_CAUSES = Set.of(Code.E037_SPINDLE_DIRECTION_BEFORE_CUT,
            Code.E038_CHUCK_OPEN_CUT, Code.E039_FEED_NOT_SET, Code.E041_G50_NOT_SET_BEFORE_CUT,
            Code.E050_S_BEFORE_G50, Code.E051_SPINDLE_DIRECTION, Code.E103_FEED_ABOVE_MAXIMUM,
            Code.E104_FEED_PER_REV_NO_SPEED);
    private static final int NOTE_LINES = 5;

    private final Diagnostics out;
    private final Map<Code, Cause> causes = new EnumMap<>(Code.class);
    /** Findings of contour blocks read ahead, so that following them again (G70) does not repeat them. */
    private final Set<String> aside = new HashSet<>();

    /** A root cause already reported, and the later blocks that broke the same rule. */
    private static final class Cause {
        final Diagnostic first;
        int later;
        final StringBuilder lines = new StringBuilder();

        Cause(Diagnostic first) {
            this.first = first;
        }
    }

    FindingReport(Diagnostics out) {
        this.out = out;
    }

    /**
     * Reports the block's findings ({@code found}), folding a repeated root cause into its first
     * report; a block of a cycle adds a note naming its pass, and a contour block followed again
     * (G70) does not repeat what reading it ahead already reported.
     */
    void block(Diagnostics found, RawBlock b, CycleOrigin origin) {
        if (found.size() == 0) {
            return;
        }
        for (Diagnostic diag : found.sorted()) {
            if (origin != null && origin.again() && aside.contains(key(diag))) {
                continue;
            }
            Cause c = causes.get(diag.code());
            if (c != null && diag.severity() == Severity.ERROR) {
                c.later++;
                if (c.later <= NOTE_LINES) {
                    c.lines.append(c.lines.length() == 0 ? "" : ", ").append(b.line());
                } else if (c.later == NOTE_LINES + 1) {
                    c.lines.append(", ...");
                }
                continue;
            }
            if (ROOT_CAUSES.contains(diag.code())) {
                causes.put(diag.code(), new Cause(diag));
            }
            out.report(diag);
            if (origin != null && origin.noted() && diag.severity() != Severity.NOTE) {
                out.report(origin.note(diag.span()));
            }
        }
    }

    /** Reports findings of a block checked outside the flow (a contour read ahead), remembering them. */
    void aside(Diagnostics found) {
        for (Diagnostic diag : found.sorted()) {
            if (aside.add(key(diag))) {
                out.report(diag);
            }
        }
    }

    /** Whether a root cause is open (reported, not yet closed by a clean cut). */
    boolean open() {
        return !causes.isEmpty();
    }

    /** A clean cut, or the end: every prerequisite holds again, so a later break is a new cause. */
    void closeCauses() {
        if (causes.isEmpty()) {
            return;
        }
        for (Cause c : causes.values()) {
            note(c);
        }
        causes.clear();
    }

    private void note(Cause c) {
        if (c.later > 0) {
            out.report(new Diagnostic(Code.E115_SAME_CAUSE, Severity.NOTE, c.first.span(),
                    List.of(Integer.toString(c.later), c.lines.toString()), c.first.origin().withoutCalls()));
        }
    }

    /** Adds what only the other position of the block delete switch found, each with a note saying so. */
    void merge(Diagnostics found, boolean switchOn) {
        Set<String> mine = new HashSet<>();
        for (Diagnostic d : out.sorted()) {
            mine.add(key(d));
        }
        for (Diagnostic d : found.sorted()) {
            if (mine.add(key(d))) {
                out.report(d);
                if (d.severity() != Severity.NOTE) {
                    out.report(new Diagnostic(Code.E118_BLOCK_DELETE_VARIANT, Severity.NOTE, d.span(),
                            List.of(switchOn ? "on" : "off"), d.origin().withoutCalls()));
                }
            }
        }
    }

    private static String key(Diagnostic d) {
        return d.code() + "@" + d.origin().file() + ":" + d.span() + d.args();
    }
}
