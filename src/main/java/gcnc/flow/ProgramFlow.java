package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Origin;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.MRole;
import gcnc.parse.BlockSource;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.Iterator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * The program-flow stage: the blocks of a program in the order the control runs them, following
 * subprogram calls (M98 P, repeated by L or, on Fanuc, by the digits of P before the program
 * number) and returns (M99), and running Fanuc macro B statements (variables, expressions,
 * GOTO, IF, WHILE; {@link MacroLine}). The checker is handed each block once per time it runs,
 * without its flow words (M98 P L, M99), at its call depth, with the values of its macro words
 * worked out; findings in a called program are placed in its file with a note per call
 * (Diagnostics.placeIn, E136). docs/program-flow.md.
 *
 * <p>Memory: a program without a call is read one line at a time, as before. At the first call
 * the rest of the file is read and held (the called programs are after the main program's end),
 * at most {@link #HOLD_LIMIT} blocks in all, with the files beside it that calls name; past that
 * the call is E137 and calls are no longer followed. A main program is held from its first macro
 * statement on (GOTO and END jump back), up to the same limit.
 */
public final class ProgramFlow implements BlockSource {
    /** The most blocks held in memory for calls (the rest of the file after the first call, and the called files), and for jumps. */
    public static final int HOLD_LIMIT = 200_000;
    /** How many times a WHILE loop may run from one entry, and a GOTO jump back, before it is taken for endless (E149). */
    public static final int LOOP_LIMIT = 100_000;
    /** How many macro statements a run may execute in all (loops inside loops); past it jumps are no longer followed (E149). */
    public static final int STEP_LIMIT = 5_000_000;
    /** The largest repeat count (L, or the leading digits of a Fanuc P): four digits. */
    private static final int MAX_REPEAT = 9999;

    private final MainFile main;
    private final MainBlocks mainBlocks;
    private final Control control;
    private final FlowCodes codes;
    private final Diagnostics diags;
    private final Library library;
    private final Variables vars = new Variables();
    /** The programs being run, innermost first; the main program at the bottom. */
    private final Deque<Frame> stack = new ArrayDeque<>();
    private final Set<Program> reportedNoM99 = Collections.newSetFromMap(new IdentityHashMap<>());
    /** How many times each GOTO (program and index) has jumped back. */
    private final Map<String, Integer> jumpsBack = new HashMap<>();
    /** The first call read the rest of the file into the library. */
    private boolean libraryRead;
    /** E137: calls are no longer followed. */
    private boolean callsOff;
    /** E137 for the main program's held blocks was reported. */
    private boolean mainFullReported;
    /** The block that ends the main program has been handed on. */
    private boolean finished;
    /** Macro statements executed so far. */
    private long steps;

    /** One program being run: where it is, how many more times it runs, its loops, and where its findings go. */
    private static final class Frame {
        final Blocks blocks;
        /** Null for the main program. */
        final Program program;
        final Origin origin;
        int next;
        int repeats;
        boolean returning;
        /** For loop ids 1-3: the index of its WHILE (-1: none), how many turns since it was entered. */
        final int[] whileAt = {-1, -1, -1, -1};
        final int[] turns = new int[4];
        /** The last jump was an END going back to its WHILE. */
        boolean cameBack;

        Frame(Blocks blocks, Program program, Origin origin, int repeats) {
            this.blocks = blocks;
            this.program = program;
            this.origin = origin;
            this.repeats = repeats;
        }

        /** Runs the program again from its start (the next repeat). */
        void restart() {
            next = 0;
            returning = false;
            java.util.Arrays.fill(whileAt, -1);
            cameBack = false;
        }
    }

    /**
     * @param folder where the files of called programs that are not in the program's own file are
     *               looked for (the program file's folder); empty: only its own file
     */
    public ProgramFlow(BlockSource reader, Control control, Diagnostics diags, Optional<Path> folder) {
        this(reader, control, diags, folder, HOLD_LIMIT);
    }

    ProgramFlow(BlockSource reader, Control control, Diagnostics diags, Optional<Path> folder, int holdLimit) {
        this.codes = new FlowCodes(control);
        this.main = new MainFile(reader, control, codes, p -> diags.report(MainFile.neverCalled(p)));
        this.mainBlocks = new MainBlocks(main, holdLimit);
        this.control = control;
        this.diags = diags;
        this.library = new Library(folder, diags, holdLimit, control.macros());
        stack.push(new Frame(mainBlocks, null, Origin.PROGRAM, 1));
    }

    @Override
    public RawBlock next() throws IOException {
        while (true) {
            Frame f = stack.peek();
            RawBlock b = f.returning ? null : f.blocks.get(f.next);
            if (f.program != null && b == null) {
                if (!f.returning && reportedNoM99.add(f.program)) {
                    diags.report(Diagnostic.error(Code.E140_NO_M99, f.program.start(), f.program.name())
                            .in(f.program.origin()));
                }
                if (--f.repeats == 0) {
                    stack.pop();
                } else {
                    f.restart();
                }
                continue;
            }
            if (b == null) {
                diags.placeIn(Origin.PROGRAM);
                if (libraryRead && !callsOff) {
                    library.neverCalled();
                }
                return null;
            }
            int at = f.next++;
            diags.placeIn(f.origin);
            if (f.program == null) {
                if (mainBlocks.full() && !mainFullReported) {
                    mainFullReported = true;
                    diags.error(Code.E137_TOO_LONG_TO_HOLD, b.last(), mainBlocks.limit());
                }
                if (finished) {
                    return b; // after the end: never run (the checker reports it, E053); its calls are not followed
                }
                finished = main.isEnd(b);
                if (main.isPlain(b)) {
                    return b; // no call, no return, no macro statement: as the parser read it
                }
            }
            if (b.macro() != null) {
                b = macro(b, f, at);
                if (b == null) {
                    continue;
                }
            }
            return follow(b, f);
        }
    }

    @Override
    public int lines() {
        return main.lines();
    }

    // ---- macro statements ----

    /** Runs a macro line of frame {@code f} at index {@code at}: the words it comes to, or null (it moved the frame, or only set variables). */
    private RawBlock macro(RawBlock b, Frame f, int at) throws IOException {
        MacroLine.Outcome o = MacroLine.run(b, vars, diags);
        if (++steps == STEP_LIMIT) {
            diags.error(Code.E149_MACRO_ENDLESS_LOOP, b.last(), "the program", b.line(), STEP_LIMIT);
        }
        if (o instanceof MacroLine.Words w) {
            List<Word> words = w.words();
            return new RawBlock(b.line(), words, words.get(words.size() - 1).span(), w.malformed(), b.blockDelete(), 0);
        }
        if (steps >= STEP_LIMIT) {
            return null; // jumps are no longer followed: the program runs on to its end
        }
        if (o instanceof MacroLine.Jump j) {
            goTo(f, j, at);
        } else if (o instanceof MacroLine.Loop l) {
            loop(f, l, at);
        } else if (o instanceof MacroLine.EndLoop e) {
            endLoop(f, e);
        }
        return null;
    }

    /** GOTO n: the block labelled N n, searched from the GOTO to the end, then from the start. */
    private void goTo(Frame f, MacroLine.Jump j, int at) throws IOException {
        int target = -1;
        for (int k = at + 1; target < 0; k++) {
            RawBlock b = f.blocks.get(k);
            if (b == null) {
                break;
            }
            if (label(b) == j.label()) {
                target = k;
            }
        }
        for (int k = f.blocks.first(); target < 0 && k <= at; k++) {
            RawBlock b = f.blocks.get(k);
            if (b != null && label(b) == j.label()) {
                target = k;
            }
        }
        if (target < 0) {
            diags.error(Code.E141_NO_JUMP_TARGET, j.at(), j.text(), "N" + j.label(), firstLine(f));
            return;
        }
        if (target <= at) {
            String key = System.identityHashCode(f.blocks) + ":" + at;
            int n = jumpsBack.merge(key, 1, Integer::sum);
            if (n > LOOP_LIMIT) {
                diags.error(Code.E149_MACRO_ENDLESS_LOOP, j.at(), j.text(), j.at().line(), LOOP_LIMIT);
                return;
            }
        }
        f.next = target;
    }

    /** WHILE [..] DO m: on into the loop while it holds (up to the limit), else after its END m. */
    private void loop(Frame f, MacroLine.Loop l, int at) throws IOException {
        int id = l.id();
        boolean again = f.cameBack && f.whileAt[id] == at;
        f.cameBack = false;
        f.whileAt[id] = at;
        f.turns[id] = again ? f.turns[id] + 1 : 1;
        boolean holds = l.holds();
        if (holds && f.turns[id] > LOOP_LIMIT) {
            diags.error(Code.E149_MACRO_ENDLESS_LOOP, l.at(), l.text(), l.at().line(), LOOP_LIMIT);
            holds = false;
        }
        if (holds) {
            return;
        }
        f.whileAt[id] = -1;
        for (int k = at + 1; ; k++) {
            RawBlock b = f.blocks.get(k);
            if (b == null) {
                diags.error(Code.E141_NO_JUMP_TARGET, l.at(), l.text(), "END " + id, firstLine(f));
                return;
            }
            if (b.macro() != null && MacroLine.isEnd(b.macro(), id)) {
                f.next = k + 1;
                return;
            }
        }
    }

    /** END m: back to the WHILE of loop m. */
    private void endLoop(Frame f, MacroLine.EndLoop e) throws IOException {
        int at = f.whileAt[e.id()];
        if (at < 0 || at < f.blocks.first()) {
            diags.error(Code.E141_NO_JUMP_TARGET, e.at(), e.text(), "WHILE [..] DO " + e.id(), firstLine(f));
            return;
        }
        f.next = at;
        f.cameBack = true;
    }

    /** A block's N label: its first word's, or a macro line's leading N; -1 for none. */
    private static long label(RawBlock b) {
        if (b.macro() != null) {
            return MacroLine.label(b.macro());
        }
        return !b.words().isEmpty() && b.words().get(0).letter() == gcnc.ir.Letter.N
                ? FlowWords.digits(b.words().get(0).number()) : -1;
    }

    /** The line of the first block a jump can reach. */
    private static int firstLine(Frame f) throws IOException {
        RawBlock b = f.blocks.get(f.blocks.first());
        return b == null ? 1 : b.line();
    }

    // ---- calls and returns ----

    /** The block as the checker is given it, after following its call or return ({@code f}: the program it is in). */
    private RawBlock follow(RawBlock b, Frame f) throws IOException {
        int depth = stack.size() - 1;
        if (b.malformed() || b.blockDelete() > 0 && control.blockDelete() == Control.BlockDelete.ON) {
            return depth == 0 ? b : b.called(b.words(), b.last(), depth);
        }
        FlowWords w = FlowWords.of(b, codes);
        if (w == null) {
            return depth == 0 ? b : b.called(b.words(), b.last(), depth);
        }
        if (w.role() == MRole.RETURN) {
            return giveBack(b, w, f, depth);
        }
        Frame callee = call(b, w, f);
        RawBlock rest = b.called(w.rest(), last(w.rest(), w.flow()), depth);
        if (callee != null) {
            stack.push(callee);
        }
        return rest;
    }

    /** M99: the end of a called program; in the main program its end, with a warning (E139). M99 P: E110. */
    private RawBlock giveBack(RawBlock b, FlowWords w, Frame f, int depth) {
        if (w.p() != null) {
            diags.error(Code.E110_NOT_SUPPORTED_YET, w.p().span(), w.flow() + " " + w.p(),
                    "return to a sequence number of the caller");
        }
        if (f.program == null) {
            diags.report(Diagnostic.warning(Code.E139_M99_IN_MAIN, w.flow().span(), w.flow()));
            List<Word> kept = new ArrayList<>(b.words());
            kept.remove(w.p());
            return b.called(kept, last(kept, w.flow()), 0); // the checker takes M99 as the end
        }
        f.returning = true;
        return b.called(w.rest(), last(w.rest(), w.flow()), depth);
    }

    /** The frame an M98 starts, or null after reporting why it does not run. */
    private Frame call(RawBlock b, FlowWords w, Frame caller) throws IOException {
        Word at = w.flow();
        if (w.p() == null) {
            diags.error(Code.E132_CALL_WITHOUT_P, at.span(), at);
            return null;
        }
        long p = FlowWords.digits(w.p().number());
        if (p < 0) {
            diags.error(Code.E130_NO_PROGRAM_HERE, w.p().span(), w.p().number());
            return null;
        }
        long number = p;
        long repeats = 1;
        boolean countInP = control.calls().countInP() && w.p().number().length() > 4;
        if (countInP) {
            number = p % 10_000;
            repeats = p / 10_000 == 0 ? 1 : p / 10_000;
            if (repeats > MAX_REPEAT) {
                diags.error(Code.E135_BAD_REPEAT_COUNT, w.p().span(), w.p());
                return null;
            }
        }
        if (w.l() != null) {
            if (countInP && p / 10_000 > 0) {
                diags.error(Code.E143_TWO_REPEAT_COUNTS, w.l().span(), w.written());
                return null;
            }
            repeats = FlowWords.digits(w.l().number());
            if (repeats < 1 || repeats > MAX_REPEAT) {
                diags.error(Code.E135_BAD_REPEAT_COUNT, w.l().span(), w.l());
                return null;
            }
        }
        if (!libraryRead && !callsOff) {
            libraryRead = true;
            if (!main.readAll(library.room(), library::add)) {
                callsOff = true;
            }
        }
        if (callsOff) {
            diags.error(Code.E137_TOO_LONG_TO_HOLD, at.span(), library.limit());
            return null;
        }
        String chain = recursion(number);
        if (chain != null) {
            diags.error(Code.E133_RECURSIVE_CALL, at.span(), Program.name(number), chain);
            return null;
        }
        if (stack.size() - 1 >= control.calls().depth()) {
            diags.error(Code.E134_CALLS_TOO_DEEP, at.span(), control.calls().depth(), path(number));
            return null;
        }
        Program program = library.find(number, w.p(), at.span());
        if (program == null) {
            return null;
        }
        List<Origin.Call> calls = new ArrayList<>();
        calls.add(new Origin.Call(program.name(), b.line(), w.written(),
                caller.program == null ? null : caller.program.file()));
        calls.addAll(caller.origin.calls());
        return new Frame(program, program, new Origin(program.file(), calls), (int) repeats);
    }

    /** The chain of calls that comes back to {@code number} ("O1000 > O2000 > O1000"), or null. */
    private String recursion(long number) {
        List<String> names = new ArrayList<>();
        if (main.number() >= 0) {
            names.add("O" + Program.name(main.number()));
        }
        for (Iterator<Frame> i = stack.descendingIterator(); i.hasNext(); ) {
            Frame f = i.next();
            if (f.program != null) {
                names.add("O" + f.program.name());
            }
        }
        int from = names.indexOf("O" + Program.name(number));
        if (from < 0) {
            return null;
        }
        names.add("O" + Program.name(number));
        return String.join(" > ", names.subList(from, names.size()));
    }

    /** The calls in progress and the one asked for: "O1000 > O2000 > ... > O5000". */
    private String path(long number) {
        List<String> names = new ArrayList<>();
        for (Iterator<Frame> i = stack.descendingIterator(); i.hasNext(); ) {
            Frame f = i.next();
            if (f.program != null) {
                names.add("O" + f.program.name());
            }
        }
        names.add("O" + Program.name(number));
        return String.join(" > ", names);
    }

    private static gcnc.diag.Span last(List<Word> words, Word otherwise) {
        return words.isEmpty() ? otherwise.span() : words.get(words.size() - 1).span();
    }
}
