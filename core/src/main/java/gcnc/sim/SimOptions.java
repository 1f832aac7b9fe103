package gcnc.sim;

import java.util.Optional;

/**
 * How to simulate: an optional stock override (else the profile's {@code stock.*}), the
 * conformance tolerance in counts, whether to keep the path for an SVG, and an optional trace
 * sink that receives one line per directive (streamed, never stored).
 */
public record SimOptions(Optional<StockSize> stock, double tolerance, boolean keepPath, Appendable trace) {
    public static final double DEFAULT_TOLERANCE = 1.5;

    public static SimOptions defaults() {
        return new SimOptions(Optional.empty(), DEFAULT_TOLERANCE, false, null);
    }

    public SimOptions withStock(StockSize s) {
        return new SimOptions(Optional.of(s), tolerance, keepPath, trace);
    }

    public SimOptions withPath() {
        return new SimOptions(stock, tolerance, true, trace);
    }

    public SimOptions withTrace(Appendable sink) {
        return new SimOptions(stock, tolerance, keepPath, sink);
    }
}
