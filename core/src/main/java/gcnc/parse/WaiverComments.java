package gcnc.parse;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.diag.Waivers;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Finds the waivers in a program's comments, {@code (GCNC ALLOW E642: reason)} and {@code (GCNC
 * ALLOW E642 FILE: reason)} (docs/language.md, "Waivers"), line by line as {@link BlockReader}
 * reads them, and hands each to the run's {@link Waivers} with the line of the block it applies
 * to: the block of the line where the comment ends, or, when that line has no words, the next
 * block read. A comment may span lines where the control's comments do (the thesis's control);
 * its text is then joined with single blanks. A line without a '(' (and not inside a comment)
 * costs one scan for the character. A waiver without a reason (E670), with a code gcnc does not
 * have (E671) or in no waiver's form (E676) is a warning at its '(' and waives nothing.
 */
final class WaiverComments {
    /** The longest comment text followed across lines; a longer one is no waiver. */
    private static final int MAX_TEXT = 4_000;
    private static final Pattern START = Pattern.compile("\\s*GCNC\\s+ALLOW\\b(.*)", Pattern.CASE_INSENSITIVE | Pattern.DOTALL);
    private static final Pattern FORM = Pattern.compile("\\s+E(\\d{1,4})(\\s+FILE)?\\s*(?::(.*))?",
            Pattern.CASE_INSENSITIVE | Pattern.DOTALL);

    private final Diagnostics diags;
    /** The file whose comments these are (null: the program's own). */
    private final String file;
    /** Haas, Fanuc: a comment ends at its line's end at the latest; else it may go on to later lines. */
    private final boolean lineComments;
    /** The text of a comment that goes on past its line, and where its '(' is; null when none is open. */
    private StringBuilder open;
    private Span openAt;
    /** Block waivers read whose block has not come yet (a waiver on a line of its own). */
    private final List<Waivers.Waiver> pending = new ArrayList<>();

    WaiverComments(Diagnostics diags, boolean lineComments, String file) {
        this.diags = diags;
        this.file = file;
        this.lineComments = lineComments;
    }

    /** Reads the comments of one physical line. */
    void line(char[] cs, int length, int number) {
        int i = 0;
        if (open != null) {
            int close = indexOf(cs, ')', 0, length);
            appendText(cs, 0, close < 0 ? length : close);
            if (close < 0) {
                return;
            }
            closed(open.toString(), openAt, number);
            open = null;
            i = close + 1;
        }
        for (int at = indexOf(cs, '(', i, length); at >= 0; at = indexOf(cs, '(', i, length)) {
            int close = indexOf(cs, ')', at + 1, length);
            if (close < 0) {
                if (!lineComments && mayBeWaiver(cs, at + 1, length)) {
                    open = new StringBuilder();
                    openAt = Span.of(number, at + 1);
                    appendText(cs, at + 1, length);
                } else if (lineComments) {
                    closed(new String(cs, at + 1, length - at - 1), Span.of(number, at + 1), number);
                }
                return;
            }
            if (mayBeWaiver(cs, at + 1, close)) {
                closed(new String(cs, at + 1, close - at - 1), Span.of(number, at + 1), number);
            }
            i = close + 1;
        }
    }

    /** A block on {@code line} was read: the waivers waiting for their block apply to it. */
    void block(int line) {
        for (Waivers.Waiver w : pending) {
            diags.waivers().add(new Waivers.Waiver(w.code(), false, w.reason(), w.at(), w.file(), line));
        }
        pending.clear();
    }

    /** The end of the input: a waiver no block follows applies at its own line (and will waive nothing there). */
    void end() {
        for (Waivers.Waiver w : pending) {
            diags.waivers().add(w);
        }
        pending.clear();
        open = null;
    }

    private void appendText(char[] cs, int from, int to) {
        if (open.length() > 0) {
            open.append(' ');
        }
        if (open.length() + to - from <= MAX_TEXT) {
            open.append(cs, from, to - from);
        }
    }

    /** Whether the comment text from {@code from} starts (after blanks) with "GCNC", any case. */
    private static boolean mayBeWaiver(char[] cs, int from, int to) {
        int i = from;
        while (i < to && (cs[i] == ' ' || cs[i] == '\t')) {
            i++;
        }
        return to - i >= 4 && (cs[i] | 0x20) == 'g' && (cs[i + 1] | 0x20) == 'c' && (cs[i + 2] | 0x20) == 'n'
                && (cs[i + 3] | 0x20) == 'c';
    }

    /** A whole comment's text ({@code at}: its '('; it ends on {@code line}). */
    private void closed(String text, Span at, int line) {
        Matcher start = START.matcher(text);
        if (!start.matches()) {
            return; // a comment that only starts with GCNC
        }
        Matcher form = FORM.matcher(start.group(1));
        if (!form.matches()) {
            diags.report(Diagnostic.warning(Code.E676_WAIVER_FORM, at, excerpt(text)));
            return;
        }
        String id = "E" + form.group(1);
        Optional<Code> code = Code.find(Integer.parseInt(form.group(1)));
        if (code.isEmpty()) {
            diags.report(Diagnostic.warning(Code.E671_WAIVER_UNKNOWN_CODE, at, id));
            return;
        }
        String reason = form.group(3) == null ? "" : form.group(3).strip().replaceAll("\\s+", " ");
        if (reason.isEmpty()) {
            diags.report(Diagnostic.warning(Code.E670_WAIVER_NO_REASON, at, code.get().id()));
            return;
        }
        Waivers.Waiver w = new Waivers.Waiver(code.get(), form.group(2) != null, reason, at, file, line);
        if (w.wholeFile()) {
            diags.waivers().add(w);
        } else {
            pending.add(w);
        }
    }

    private static String excerpt(String text) {
        String t = text.strip().replaceAll("\\s+", " ");
        return t.length() <= 60 ? t : t.substring(0, 57) + "...";
    }

    private static int indexOf(char[] cs, char c, int from, int to) {
        for (int i = from; i < to; i++) {
            if (cs[i] == c) {
                return i;
            }
        }
        return -1;
    }
}
