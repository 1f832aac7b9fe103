package gcnc.ir;

import gcnc.diag.Span;

/**
 * One word of a block as written: its letter (upper case), the exact text of its number (sign and
 * point included: "01" for G01, "1" for g1, "+5." for X+5.) and where it starts. A letter without
 * a number is error 6, reported by the parser, so a well-formed block never has an empty number.
 */
public record Word(Letter letter, String number, Span span) {
    @Override
    public String toString() {
        return letter + number;
    }
}
