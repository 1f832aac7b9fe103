package gcnc.post;

import java.util.Locale;

/**
 * The text of a generated program, written block by block the way the posts' writeBlock does:
 * an optional sequence number, optional '/' for an optional operation, words separated by a
 * space or by nothing. Numbers are given in mm and written in program units (inch for the haas
 * profile) as the posts' formats write them: 4 decimals in inch, 3 in mm, always a decimal point.
 */
final class Blocks {
    private final StringBuilder text = new StringBuilder();
    private final double unit;
    private int sequence = 10;
    /** Sequence numbers on every block (showSequenceNumbers = true). */
    boolean numbered;
    /** No spaces between words. */
    boolean tight;
    /** Blocks of an optional operation: '/' first. */
    boolean optional;
    /** One-digit G and M codes with a leading zero: G00, M03. */
    boolean zeros;

    Blocks(double unit) {
        this.unit = unit;
    }

    /** A block; its sequence number when they are on. */
    void block(String... words) {
        block(numbered ? sequence : -1, words);
    }

    /** A block that must carry N{@code n} (a G70/G71 contour's first and last block). */
    void numberedBlock(int n, String... words) {
        block(n, words);
    }

    /**
     * The number a block written after {@code blocks} more numbered blocks gets: where a G71's
     * contour starts when its G71 block(s) come first. The counter then runs on from there only
     * once {@link #skipNumbers} moves it past the contour.
     */
    int numberAfter(int blocks) {
        return numbered ? sequence + 5 * blocks : sequence;
    }

    /** Sequence numbers go on after {@code last} (a contour numbered up to it). */
    void skipNumbers(int last) {
        sequence = Math.max(sequence, last + 5);
    }

    private void block(int n, String... words) {
        StringBuilder b = new StringBuilder();
        if (optional) {
            b.append('/');
        }
        if (n >= 0) {
            b.append('N').append(n);
            if (n == sequence) {
                sequence += 5;
            }
        }
        for (String w : words) {
            if (w.isEmpty()) {
                continue;
            }
            if (b.length() > 0 && b.charAt(b.length() - 1) != '/' && !(tight && w.charAt(0) != '(')) {
                b.append(' ');
            }
            if (zeros) {
                w = w.replaceAll("\\b([GM])(\\d)\\b", "$10$2");
            }
            b.append(tight && w.charAt(0) != '(' ? w.replace(" ", "") : w);
        }
        line(b.toString());
    }

    /** A line as it is (%, O number, comments, a blank line). */
    void line(String s) {
        text.append(s).append('\n');
    }

    /** Where the text ends now, for {@link #insert}. */
    int mark() {
        return text.length();
    }

    /** Text inserted where {@link #mark} was taken (the header's tool list, known only at the end). */
    void insert(int mark, String s) {
        text.insert(mark, s);
    }

    /** Characters with no line end. */
    void raw(String s) {
        text.append(s);
    }

    String text() {
        return text.toString();
    }

    /** A length in mm as the post writes it in program units: "2.", "0.0625", "-1.5". */
    String num(double mm) {
        double v = mm / unit;
        String t = String.format(Locale.ROOT, unit == 1 ? "%.3f" : "%.4f", v);
        t = t.replaceAll("0+$", "");
        if (t.equals("-0.")) {
            t = "0.";
        }
        return t;
    }

    /** A diameter word: X or U carry diameters on both lathes (xFormat scale 2 in the posts). */
    String x(double diameterMm) {
        return "X" + num(diameterMm);
    }

    String z(double mm) {
        return "Z" + num(mm);
    }

    /** A value in whole least increments with no decimal point (fanuc G76/G74/G75 P and Q: 1000 = 1 mm). */
    static String micro(double mm) {
        return String.valueOf(Math.round(mm * 1000));
    }
}
