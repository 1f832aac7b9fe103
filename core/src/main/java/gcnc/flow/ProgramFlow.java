package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Origin;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.MachineProfile;
import gcnc.machine.MRole;
import gcnc.machine.Units;
import gcnc.parse.BlockSource;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * The program-flow stage: the blocks of a program in the order the control runs them, following
 * subprogram calls (M98 P, repeated by L or, on Fanuc, by the digits of P before the program
 * number), macro calls (G65 P with arguments, {@link MacroArguments}) and returns (M99), and running
 * Fanuc macro B statements (variables, expressions, GOTO, IF, WHILE; {@link MacroLine}). The checker
 * is handed each block once per time it runs, without its flow words (M98 P L, G65 P L and its
 * arguments, M99), at its call depth, with the values of its macro words
 * worked out, and with where it comes from ({@link RawBlock#origin}: a called program's file and
 * the calls that led to it); findings in a called program are placed there with a note per call
 * (E136). docs/program-flow.md.
 *
 * <p>Memory: a program without a call is read one line at a time, as before. At the first call
 * the rest of the file is read and held (the called programs are after the main program's end),
 * at most {@link #holdLimit()} blocks in all, with the files beside it that calls name; past that
 * the call is E137 and calls are no longer followed. A main program is held from its first macro
 * statement on (GOTO and END jump back), up to the same limit.
 */
public final class ProgramFlow implements BlockSource {
    /** The most blocks held in memory for calls (the rest of the file after the first call, and the called files), and for jumps. */
    public static final int HOLD_LIMIT = 200_000;
    /**
     * Bytes of heap allowed per block held: a held block takes about 400 bytes, so a quarter to a
     * half of the heap at most. In a small heap ({@code -Xmx64m}: 65,536 blocks) the limit is lower
     * than {@link #HOLD_LIMIT}, so that holding ends with E137 and never runs the JVM out of memory.
     */
    private static final long HEAP_PER_BLOCK = 1024;
    /** How many times a WHILE loop may run from one entry, and a GOTO jump back, before it is taken for endless (E149). */
    public static final int LOOP_LIMIT = 100_000;
    /**
     * The run's budget: how many blocks it may go through again in all (a loop's passes after its
     * first, blocks of called programs, macro statements; loops inside loops, repeats inside repeats:
     * L9999 four deep would never end). A loop still running past it is taken for endless (E710; E149
     * when no loop runs), and calls and jumps are no longer followed. A loop that comes round with
     * every variable unchanged is endless at once (E149, {@link MacroJumps}): the GOTO loop of a
     * 70-line program that changes nothing ran 100,000 passes, 7 million blocks, 21 s and 493 MB
     * before E149; now two passes. The budget ends a loop that does change something and never ends
     * (a counter past its bound): five million blocks, a few seconds of checking; the longest
     * legitimate macro runs gcnc is tested with go through 2 million (BoundedRunTest: 400,000 moves
     * from two nested WHILEs).
     */
    public static final int STEP_LIMIT = 5_000_000;
    private final MainFile main;
    private final MainBlocks mainBlocks;
    private final Control control;
    private final FlowCodes codes;
    private final Diagnostics diags;
    private final Library library;
    private final Variables vars = new Variables();
    /** How a number written without a decimal point reads, in G21 (mm) and in G20 (in): a macro call's arguments. */
    private final double noPointMm;
    private final double noPointInch;
    /** The input units in force (G20/G21) as the blocks handed on set them: a macro call's arguments read in them. */
    private Units units;
    /** The programs being run, innermost first; the main program at the bottom. */
    private final CallStack stack;
    /** The programs (file and name) already reported for ending without M99 (E140). */
    private final Set<String> reportedNoM99 = new HashSet<>();
    /** The main program's blocks that an M97 call ran (a local subprogram after M30 is not "after the end"). */
    private final BitSet ranLocally = new BitSet();
    /** The blocks after the main program's end that a GOTO's or an M97's label can reach. */
    private final ReachableAfterEnd afterEnd;
    private final MacroJumps jumps;
    /** The first call read the rest of the file into the library. */
    private boolean libraryRead;
    /** E137: calls are no longer followed. */
    private boolean callsOff;
    /** E137 for the main program's held blocks was reported. */
    private boolean mainFullReported;
    /** The block that ends the main program has been handed on. */
    private boolean finished;
    /** The blocks gone through again, against {@link #STEP_LIMIT}. */
    private final StepBudget budget;
    /** One past the furthest block of the main program's own frame run so far: a block before it runs again. */
    private int mainReached;

    /**
     * @param machine the machine the program runs on: its control, and how it reads a number
     *                without a decimal point in its power-up units (a macro call's arguments)
     * @param folder  where the files of called programs that are not in the program's own file are
     *                looked for (the program file's folder); empty: only its own file
     */
    public ProgramFlow(BlockSource reader, MachineProfile machine, Diagnostics diags, Optional<Path> folder) {
        this(reader, machine, diags, folder, holdLimit());
    }

    ProgramFlow(BlockSource reader, MachineProfile machine, Diagnostics diags, Optional<Path> folder, int holdLimit) {
        Control control = machine.control();
        this.noPointMm = machine.noPointMm();
        this.noPointInch = machine.noPointInch();
        this.units = machine.units();
        this.codes = new FlowCodes(control);
        this.main = new MainFile(reader, control, codes, p -> diags.report(MainFile.neverCalled(p)));
        this.mainBlocks = new MainBlocks(main, holdLimit);
        this.control = control;
        this.diags = diags;
        this.library = new Library(folder, diags, holdLimit, control.macros(), control.lineComments());
        this.jumps = new MacroJumps(diags, vars);
        this.stack = new CallStack(Frame.main(mainBlocks), main, control.calls().depth(), diags);
        this.afterEnd = new ReachableAfterEnd(codes, diags);
        this.budget = new StepBudget(STEP_LIMIT, diags, jumps, stack);
    }

    /** Every file beside the program that a call looked for, found or not ({@link Library#lookedFor}). */
    public java.util.List<Path> calledFiles() {
        return java.util.List.copyOf(library.lookedFor());
    }

    /** The most blocks this JVM holds: {@link #HOLD_LIMIT}, or one per KiB of its largest heap if that is fewer. */
    public static int holdLimit() {
        return (int) Math.min(HOLD_LIMIT, Runtime.getRuntime().maxMemory() / HEAP_PER_BLOCK);
    }

    @Override
    public RawBlock next() throws IOException {
        while (true) {
            Frame f = stack.peek();
            RawBlock b = f.returning ? null : f.blocks.get(f.next);
            if (!f.isMain() && b == null) {
                endPass(f);
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
            b = b.from(f.origin);
            diags.placeIn(b.origin()); // findings made without an origin of their own belong to it
            boolean again = f.isMain() && at < mainReached;
            if (f.isMain() && !again) {
                mainReached = at + 1;
            }
            if (!f.isMain() || b.macro() != null || again) {
                budget.step(b);
            }
            if (f.blocks == mainBlocks && !f.isMain()) {
                ranLocally.set(at);
            }
            units(b);
            if (f.isMain()) {
                if (mainBlocks.full() && !mainFullReported) {
                    mainFullReported = true;
                    diags.error(Code.E137_TOO_LONG_TO_HOLD, b.last(), mainBlocks.limit());
                }
                if (finished) {
                    if (ranLocally.get(at) || afterEnd.reachable(b)) {
                        continue; // an M97 local subprogram or a GOTO's label after M30: not "after the end"
                    }
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
                units(b);
            }
            b = follow(b, f);
            if (b != null) {
                return b;
            }
        }
    }

    @Override
    public int lines() {
        return main.lines();
    }

    /** A called program's pass is over (M99, or its end: E140): the next repeat, or back to the caller. */
    private void endPass(Frame f) {
        if (!f.returning && reportedNoM99.add(f.file + ":" + f.name)) {
            diags.report(Diagnostic.error(Code.E140_NO_M99, f.start, f.name)
                    .in(f.file == null ? Origin.PROGRAM : Origin.file(f.file)));
        }
        if (--f.repeats == 0) {
            stack.pop();
            if (f.ownLocals) {
                vars.leave();
            }
        } else {
            f.restart();
        }
    }

    /** Blocks gone through again so far ({@link StepBudget}): what a test bounds instead of the time. */
    long steps() {
        return budget.steps();
    }

    // ---- macro statements ----

    /** Runs a macro line of frame {@code f} at index {@code at}: the words it comes to, or null (it moved the frame, or only set variables). */
    private RawBlock macro(RawBlock b, Frame f, int at) throws IOException {
        MacroLine.Outcome o = MacroLine.run(b, vars, diags, control.blockDelete());
        if (budget.spent() && o.kind() != MacroLine.Outcome.Kind.WORDS) {
            return null; // jumps are no longer followed: the program runs on to its end
        }
        return switch (o.kind()) {
            case WORDS -> {
                MacroLine.Words w = (MacroLine.Words) o;
                List<Word> words = w.words();
                yield new RawBlock(b.line(), words, words.get(words.size() - 1).span(), w.malformed(), w.blockDelete(),
                        0, null, 0, b.origin());
            }
            case DONE -> null;
            case JUMP -> {
                MacroLine.Jump j = (MacroLine.Jump) o;
                afterEnd.name(j.label());
                if (j.taken()) {
                    jumps.goTo(f, j, at);
                }
                yield null;
            }
            case LOOP -> {
                jumps.loop(f, (MacroLine.Loop) o, at);
                yield null;
            }
            case END_LOOP -> {
                jumps.endLoop(f, (MacroLine.EndLoop) o);
                yield null;
            }
        };
    }

    // ---- calls and returns ----

    /** The block as the checker is given it, after following its call or return ({@code f}: the program it is in). */
    private RawBlock follow(RawBlock b, Frame f) throws IOException {
        int depth = stack.size() - 1;
        if (depth > 0 && !b.malformed()) {
            b = withoutEnd(b, f);
            if (b == null) {
                return null;
            }
        }
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
        Frame callee = budget.spent() ? null : w.role() == MRole.LOCAL_CALL ? localCall(b, w, f)
                : w.arguments() != null ? macroCall(b, w, f) : call(b, w, f, control.calls().countInP());
        RawBlock rest = b.called(w.rest(), last(w.rest(), w.flow()), depth);
        if (callee != null) {
            stack.push(callee);
        }
        return rest;
    }

    /**
     * An end code (M30, M02) in a called program ends the whole run there: E685 at it, in the called
     * program, and the block goes on without it, so that the caller's blocks after the call are
     * checked as written rather than each blamed for coming after the end (E053). Null when the end
     * code was the block's only word.
     */
    private RawBlock withoutEnd(RawBlock b, Frame f) {
        List<Word> kept = null;
        for (Word w : b.words()) {
            if (codes.role(w) == MRole.END) {
                diags.error(Code.E685_END_IN_CALLED_PROGRAM, w.span(), w, f.name);
                if (kept == null) {
                    kept = new ArrayList<>(b.words());
                }
                kept.remove(w);
            }
        }
        if (kept == null) {
            return b;
        }
        return kept.isEmpty() ? null : b.called(kept, kept.get(kept.size() - 1).span(), b.depth());
    }

    /** M99: the end of a called program; in the main program its end, with a warning (E139). M99 P: E110. */
    private RawBlock giveBack(RawBlock b, FlowWords w, Frame f, int depth) {
        if (w.p() != null) {
            diags.error(Code.E110_NOT_SUPPORTED_YET, w.p().span(), w.flow() + " " + w.p(),
                    "return to a sequence number of the caller");
        }
        if (f.isMain()) {
            diags.report(Diagnostic.warning(Code.E139_M99_IN_MAIN, w.flow().span(), w.flow()));
            List<Word> kept = new ArrayList<>(b.words());
            kept.remove(w.p());
            return b.called(kept, last(kept, w.flow()), 0); // the checker takes M99 as the end
        }
        f.returning = true;
        return b.called(w.rest(), last(w.rest(), w.flow()), depth);
    }

    /**
     * The frame a macro call G65 starts, with its arguments as its own level of locals, or null after
     * reporting why it does not run. Its P is the program number alone (L counts the repeats).
     */
    private Frame macroCall(RawBlock b, FlowWords w, Frame caller) throws IOException {
        Double[] arguments = MacroArguments.read(w, units, units == Units.INCH ? noPointInch : noPointMm, diags);
        Frame callee = arguments == null ? null : call(b, w, caller, false);
        if (callee != null) {
            callee.ownLocals = true;
            vars.enter(arguments);
        }
        return callee;
    }

    /** The input units a block's G20 or G21 sets, in force for the blocks after it. */
    private void units(RawBlock b) {
        List<Word> words = b.words();
        for (int i = 0, n = words.size(); i < n; i++) {
            Units u = codes.units(words.get(i));
            if (u != null) {
                units = u;
            }
        }
    }

    /**
     * The frame an M98 (or a G65) starts, or null after reporting why it does not run;
     * {@code countInP}: a P of more than four digits gives the repeats (Fanuc's M98).
     */
    private Frame call(RawBlock b, FlowWords w, Frame caller, boolean countInP) throws IOException {
        Word at = w.flow();
        CallTarget target = CallTarget.program(w, countInP, diags);
        if (target == null) {
            return null;
        }
        long number = target.number();
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
        String name = "O" + Program.name(number);
        if (!stack.mayCall(name, at)) {
            return null;
        }
        Program program = library.find(number, w.p(), at.span(), caller.origin);
        if (program == null) {
            return null;
        }
        return new Frame(program, "O" + program.name(), program.file(), program.start(), 0,
                calledFrom(caller, "O" + program.name(), program.file(), b, w), target.repeats());
    }

    /**
     * The frame a Haas M97 P n starts: the blocks of the calling program from its label N n on,
     * up to M99 (a local subprogram, usually after M30); or null after reporting why it does not
     * run. No such label: E141 at P.
     */
    private Frame localCall(RawBlock b, FlowWords w, Frame caller) throws IOException {
        Word at = w.flow();
        CallTarget called = CallTarget.label(w, diags);
        String name = called == null ? null : "N" + w.p().number();
        if (called == null || !stack.mayCall(name, at)) {
            return null;
        }
        long label = called.number();
        afterEnd.name(label);
        if (caller.blocks == mainBlocks) {
            mainBlocks.hold();
        }
        int target = MacroJumps.find(caller.blocks, label, caller.next - 1);
        if (target < 0) {
            diags.error(Code.E141_NO_JUMP_TARGET, w.p().span(), w.written(), "N" + label, MacroJumps.firstLine(caller));
            return null;
        }
        RawBlock first = caller.blocks.get(target);
        gcnc.diag.Span start = first.words().isEmpty() ? first.last() : first.words().get(0).span();
        return new Frame(caller.blocks, name, caller.file, start, target,
                calledFrom(caller, name, caller.file, b, w), called.repeats());
    }

    /** Where a called program's findings go: its file, and this call before the caller's. */
    private static Origin calledFrom(Frame caller, String name, String file, RawBlock b, FlowWords w) {
        List<Origin.Call> calls = new ArrayList<>();
        calls.add(new Origin.Call(name, b.line(), w.written(), caller.file));
        calls.addAll(caller.origin.calls());
        return new Origin(file, calls);
    }

    private static gcnc.diag.Span last(List<Word> words, Word otherwise) {
        return words.isEmpty() ? otherwise.span() : words.get(words.size() - 1).span();
    }
}
