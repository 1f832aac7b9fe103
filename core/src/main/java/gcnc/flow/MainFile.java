package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Severity;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.parse.BlockSource;
import java.io.IOException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * The program file split the way a Fanuc or Haas control stores it: the main program, up to and
 * including its first block that ends it (M30, M02, or M99 there), then the programs written after
 * it, each from its O word to the next O word or the end of the file. Blocks after the end that
 * belong to no program stay with the main program (the checker reports them: E053).
 *
 * <p>Blocks are read as they are needed (memory holds one line) until {@link #readAll} is asked,
 * at the first call: then the rest of the file is held, the main program's blocks in order and
 * the programs after it in the {@link Library}, up to the library's limit.
 */
final class MainFile {
    private final BlockSource reader;
    private final Control control;
    private final FlowCodes codes;
    /** The main program's blocks read ahead by {@link #readAll}, in order. */
    private final ArrayDeque<RawBlock> ahead = new ArrayDeque<>();
    /** Where each program after the main program's end goes when its last block has been read. */
    private Consumer<Program> programs;
    /** Whether blocks of programs after the end are kept (after the first call) or only counted. */
    private boolean keep;
    private boolean ended;
    /** The block that ends the main program, once read. */
    private RawBlock end;
    /** The last main-program block read if it has no call or return (the common case: nothing for the flow to do). */
    private RawBlock plain;
    private boolean first = true;
    /** The main program's number (its first block's O word), or -1. */
    private long number = -1;
    /** The program after the end being read: its O word, its blocks (when kept). */
    private Word openAt;
    private final List<RawBlock> open = new ArrayList<>();
    private boolean complete;

    MainFile(BlockSource reader, Control control, FlowCodes codes, Consumer<Program> neverCalled) {
        this.reader = reader;
        this.control = control;
        this.codes = codes;
        this.programs = neverCalled;
    }

    /** The main program's next block (or a block after its end outside any program); null at the end of the file. */
    RawBlock next() throws IOException {
        if (!ahead.isEmpty()) {
            return ahead.poll();
        }
        for (RawBlock b = read(); b != null || !complete; b = read()) {
            if (b != null) {
                return b;
            }
        }
        return null;
    }

    /**
     * Reads the rest of the file now, at most {@code limit} blocks: the main program's into the
     * queue {@link #next} hands on, the programs after the end to {@code library}. Returns false
     * when the limit was reached first (the rest is then read as it is needed, as before).
     */
    boolean readAll(int limit, Consumer<Program> library) throws IOException {
        programs = library;
        keep = true;
        for (int held = 0; !complete; held++) {
            if (held >= limit) {
                keep = false;
                programs = p -> { }; // calls are no longer followed: a program cut short is not one
                return false;
            }
            RawBlock b = read();
            if (b != null) {
                ahead.add(b);
            }
        }
        return true;
    }

    /** The main program's number from its O word, or -1. */
    long number() {
        return number;
    }

    /** Whether {@code b} is known to have no call or return (it was looked at when it was read). */
    boolean isPlain(RawBlock b) {
        return b == plain;
    }

    /** Whether {@code b} is the block that ends the main program (an M30, M02 or M99 written in it, or in its macro statement). */
    boolean isEnd(RawBlock b) {
        return b == end;
    }

    int lines() {
        return reader.lines();
    }

    /** The next block of the file if it belongs to the main program; null when it went to a program after the end. */
    private RawBlock read() throws IOException {
        RawBlock b = reader.next();
        if (b == null) {
            close();
            complete = true;
            return null;
        }
        Word o = b.words().isEmpty() || b.malformed() ? null : header(b);
        if (first) {
            first = false;
            if (o != null) {
                number = FlowWords.digits(o.number());
            }
        }
        if (!ended) {
            int bits = b.macro() == null ? codes.scan(b.words()) : 0;
            ended = ends(b, bits);
            if (ended) {
                end = b;
            }
            plain = b.macro() == null && (bits & FlowCodes.FLOW) == 0 ? b : null;
            return b;
        }
        if (o != null) {
            close();
            openAt = o;
        }
        if (openAt == null) {
            return b;
        }
        if (keep && o == null) {
            open.add(b);
        } else if (keep && b.words().size() > 1) {
            open.add(b.called(b.words().subList(1, b.words().size()), b.last(), 0)); // "O1000 G00 X10."
        }
        return null;
    }

    /** The block's O word when it is its first word (a program's header), else null. */
    private static Word header(RawBlock b) {
        Word w = b.words().get(0);
        return w.letter() == Letter.O ? w : null;
    }

    private void close() {
        if (openAt != null) {
            long n = FlowWords.digits(openAt.number());
            programs.accept(new Program((int) Math.max(0, Math.min(n, Integer.MAX_VALUE)), null, open,
                    openAt.span()));
            openAt = null;
            open.clear();
        }
    }

    /** Whether a main-program block ends it: an M of function end, or M99 (the control loops; E139). */
    private boolean ends(RawBlock b, int bits) {
        if (b.blockDelete() > 0 && control.blockDelete() == Control.BlockDelete.ON) {
            return false;
        }
        return b.macro() != null ? codes.endsText(b.macro()) : (bits & FlowCodes.END) != 0;
    }

    /** The note for a program after the end that nothing calls (E138 "O1000 is never run"), at its O word. */
    static Diagnostic neverCalled(Program p) {
        return new Diagnostic(Code.E138_NEVER_CALLED, Severity.NOTE, p.start(), List.of("O" + p.name()), p.origin());
    }
}
