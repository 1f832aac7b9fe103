package gcnc.sim;

import java.util.Optional;

/**
 * How to simulate: an optional stock override (else the profile's {@code stock.*}), or
 * {@code noBlank}: no blank at all, the stock checks skipped (an op-2 part held by a face it
 * already has, a casting: no bar describes them); the conformance tolerance in counts, whether to
 * keep the path for an SVG, and an optional trace sink that receives one line per directive
 * (streamed, never stored).
 */
public record SimOptions(Optional<StockSize> stock, boolean noBlank, double tolerance, boolean keepPath,
                         Appendable trace) {
    public static final double DEFAULT_TOLERANCE = 1.5;

    public SimOptions {
        if (noBlank && stock.isPresent()) {
            throw new IllegalArgumentException("a blank and no blank at once");
        }
    }

    public static SimOptions defaults() {
        return new SimOptions(Optional.empty(), false, DEFAULT_TOLERANCE, false, null);
    }

    public SimOptions withStock(StockSize s) {
        return new SimOptions(Optional.of(s), false, tolerance, keepPath, trace);
    }

    /** No blank, whatever the program's header or the profile say: the stock checks are skipped. */
    public SimOptions withoutBlank() {
        return new SimOptions(Optional.empty(), true, tolerance, keepPath, trace);
    }

    public SimOptions withPath() {
        return new SimOptions(stock, noBlank, tolerance, true, trace);
    }

    public SimOptions withTrace(Appendable sink) {
        return new SimOptions(stock, noBlank, tolerance, keepPath, sink);
    }
}
