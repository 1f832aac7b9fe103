package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.Iterator;
import java.util.List;

/**
 * The programs being run, innermost first, the main program at the bottom ({@link ProgramFlow}'s
 * frames), and whether one more call may be made on top of them: not recursive (E133), not
 * deeper than the control allows (E134).
 */
final class CallStack implements Iterable<Frame> {
    private final Deque<Frame> frames = new ArrayDeque<>();
    private final MainFile main;
    /** The most calls in progress at once (the control's {@code calls.depth}). */
    private final int depth;
    private final Diagnostics diags;

    /** A stack of the main program alone ({@code bottom}, read from {@code main}); at most {@code depth} calls on it. */
    CallStack(Frame bottom, MainFile main, int depth, Diagnostics diags) {
        frames.push(bottom);
        this.main = main;
        this.depth = depth;
        this.diags = diags;
    }

    void push(Frame f) {
        frames.push(f);
    }

    void pop() {
        frames.pop();
    }

    /** The program running now. */
    Frame peek() {
        return frames.peek();
    }

    /** How many programs are being run (1: the main program only). */
    int size() {
        return frames.size();
    }

    /** Innermost first. */
    @Override
    public Iterator<Frame> iterator() {
        return frames.iterator();
    }

    /** Whether one more call to {@code name} may be made: not recursive (E133), not too deep (E134). */
    boolean mayCall(String name, Word at) {
        String chain = recursion(name);
        if (chain != null) {
            diags.error(Code.E133_RECURSIVE_CALL, at.span(), name, chain);
            return false;
        }
        if (frames.size() - 1 >= depth) {
            diags.error(Code.E134_CALLS_TOO_DEEP, at.span(), depth, path(name));
            return false;
        }
        return true;
    }

    /** The chain of calls that comes back to {@code name} ("O1000 > O2000 > O1000"), or null. */
    private String recursion(String name) {
        List<String> names = running();
        if (main.number() >= 0) {
            names.add(0, "O" + Program.name(main.number()));
        }
        int from = names.indexOf(name);
        if (from < 0) {
            return null;
        }
        names.add(name);
        return String.join(" > ", names.subList(from, names.size()));
    }

    /** The calls in progress and the one asked for: "O1000 > O2000 > ... > O5000". */
    private String path(String name) {
        List<String> names = running();
        names.add(name);
        return String.join(" > ", names);
    }

    /** The names of the calls in progress, outermost first. */
    private List<String> running() {
        List<String> names = new ArrayList<>();
        for (Iterator<Frame> i = frames.descendingIterator(); i.hasNext(); ) {
            Frame f = i.next();
            if (!f.isMain()) {
                names.add(f.name);
            }
        }
        return names;
    }
}
