package gcnc.check.cycle;

import gcnc.diag.Code;
import gcnc.ir.Letter;
import java.util.List;

/**
 * A reason a cycle cannot be expanded, before it is placed: at the contour block of
 * {@code contourLine}, whose message starts with the cycle's name and line; or (contourLine 0) at
 * the cycle's word {@code word} (null: at its G), whose message starts with the cycle's name and
 * that word as written. {@code args} follow those.
 */
public record Fault(Code code, int contourLine, Letter word, List<String> args) implements Roughing.Outcome {
    public Fault {
        args = List.copyOf(args);
    }

    static Fault atContour(Code code, int line, String... args) {
        return new Fault(code, line, null, List.of(args));
    }

    static Fault atWord(Code code, Letter word, String... args) {
        return new Fault(code, 0, word, List.of(args));
    }
}
