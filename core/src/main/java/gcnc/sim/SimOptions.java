package gcnc.sim;

import java.util.Optional;

/**
 * How to simulate: an optional stock override (else the profile's {@code stock.*}), or
 * {@code noBlank}: no blank at all, the stock checks skipped (an op-2 part held by a face it
 * already has, a casting: no bar describes them); the conformance tolerance in counts, whether to
 * keep the path for an SVG, an optional trace sink that receives one line per directive
 * (streamed, never stored), and {@code scrubLine}: the G-code line whose first run the drawing
 * shows the stock before and after, with the tool there (0: none; the studio's scrub, only with
 * {@code keepPath}); {@code referenceStock}: the stock's full model, without the bore's shortcuts
 * ({@link #withReferenceStock}).
 */
public record SimOptions(Optional<StockSize> stock, boolean noBlank, double tolerance, boolean keepPath,
                         Appendable trace, int scrubLine, boolean referenceStock) {
    public static final double DEFAULT_TOLERANCE = 1.5;

    public SimOptions {
        if (noBlank && stock.isPresent()) {
            throw new IllegalArgumentException("a blank and no blank at once");
        }
        if (scrubLine < 0) {
            throw new IllegalArgumentException("a scrub line is 1 or more (0: none): " + scrubLine);
        }
    }

    /** Options with the stock's usual model. */
    public SimOptions(Optional<StockSize> stock, boolean noBlank, double tolerance, boolean keepPath, Appendable trace,
                      int scrubLine) {
        this(stock, noBlank, tolerance, keepPath, trace, scrubLine, false);
    }

    /** Options without a scrub. */
    public SimOptions(Optional<StockSize> stock, boolean noBlank, double tolerance, boolean keepPath, Appendable trace) {
        this(stock, noBlank, tolerance, keepPath, trace, 0);
    }

    public static SimOptions defaults() {
        return new SimOptions(Optional.empty(), false, DEFAULT_TOLERANCE, false, null);
    }

    public SimOptions withStock(StockSize s) {
        return new SimOptions(Optional.of(s), false, tolerance, keepPath, trace, scrubLine, referenceStock);
    }

    /** No blank, whatever the program's header or the profile say: the stock checks are skipped. */
    public SimOptions withoutBlank() {
        return new SimOptions(Optional.empty(), true, tolerance, keepPath, trace, scrubLine, referenceStock);
    }

    public SimOptions withPath() {
        return new SimOptions(stock, noBlank, tolerance, true, trace, scrubLine, referenceStock);
    }

    public SimOptions withTrace(Appendable sink) {
        return new SimOptions(stock, noBlank, tolerance, keepPath, sink, scrubLine, referenceStock);
    }

    /**
     * The path kept, and the stock as it stood before and after the first run of G-code line
     * {@code line}'s moves, with the tool's insert and holder where that run ended
     * ({@link Drawing#scrub}).
     */
    public SimOptions withScrub(int line) {
        return new SimOptions(stock, noBlank, tolerance, true, trace, line, referenceStock);
    }

    /**
     * The stock's full model: the bore stays the blank's whatever is cut from inside, and the
     * drawing's outline always comes from the polygons. Slower; what the fast path is tested
     * against (TurnedPartPropertyTest, BoredPartPropertyTest).
     */
    public SimOptions withReferenceStock() {
        return new SimOptions(stock, noBlank, tolerance, keepPath, trace, scrubLine, true);
    }
}
