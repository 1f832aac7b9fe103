package gcnc.sim;

/**
 * The studio's scrub ({@link SimOptions#withScrub}): the stock as it stood before and after the
 * first run of one G-code line's moves (a block, or every pass of a cycle written on it), and the
 * tool where that run ended. The run starts at the first sequence from that line and ends at the
 * next sequence from another line (or at the end of the program), so "after" is the stock the
 * next block meets. Costs nothing when no scrub is asked for: {@link MotionChecks} makes none.
 */
final class StockScrub {
    private enum State { WAITING, IN_RUN, DONE }

    private final int line;
    private final Stock stock;
    private State state = State.WAITING;
    private int first;
    private int last;
    private int tool;
    private double[][] before;
    private double[][] after;
    private Shape insert;
    private Shape holder;

    StockScrub(int line, Stock stock) {
        this.line = line;
        this.stock = stock;
    }

    /** Before sequence {@code index} (from G-code line {@code from}) is replayed. */
    void before(int from, int index) {
        if (state == State.WAITING && from == line) {
            state = State.IN_RUN;
            first = index;
            before = outline();
        } else if (state == State.IN_RUN && from != line) {
            state = State.DONE;
            after = outline();
        }
    }

    boolean inRun() {
        return state == State.IN_RUN;
    }

    /** After sequence {@code index} of the run: the tool and its parts placed at its tip (drawing mm; holder null if none). */
    void after(int index, int toolNumber, Shape insertThere, Shape holderThere) {
        last = index;
        tool = toolNumber;
        insert = insertThere;
        holder = holderThere;
    }

    /** What the drawing shows; null when the line never moved the tool. */
    Drawing.Scrub result() {
        if (state == State.WAITING) {
            return null;
        }
        if (state == State.IN_RUN) { // the run was the program's last motion
            state = State.DONE;
            after = outline();
        }
        return new Drawing.Scrub(line, first, last, tool, before[0], before[1], after[0], after[1], insert, holder);
    }

    /** The largest radius of material as points back to face (mm), as the drawing's final part; empty without a blank. */
    private double[][] outline() {
        return stock == null ? new double[][] {new double[0], new double[0]} : stock.profile();
    }
}
