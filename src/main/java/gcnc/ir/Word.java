package gcnc.ir;

import gcnc.diag.Span;

/**
 * One word of a block as written: its letter, the exact text of its number (sign and point
 * included, possibly empty: "X" alone is error 6, found by the checker) and where it starts.
 */
public record Word(Letter letter, String number, Span span) {
    @Override
    public String toString() {
        return letter + number;
    }
}
