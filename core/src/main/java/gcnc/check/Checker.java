package gcnc.check;

import gcnc.check.action.SyntaxAction;
import gcnc.check.action.SyntaxActions;
import gcnc.check.block.BlockCheck;
import gcnc.check.block.BlockChecks;
import gcnc.check.geom.Coordinates;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Severity;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.MachineProfile;
import gcnc.tables.Tables;
import java.util.BitSet;
import java.util.EnumMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * The checking stage: each block's words go through the thesis's syntax actions, then the
 * end-of-block operations in their fixed order, then motion building. The first error of a block
 * is reported and the block is dropped; the modal state changes only for a block without errors,
 * or one whose only errors are broken prerequisites ({@link #recover}); a block rejected for
 * anything else still keeps its unambiguous modal words ({@link Salvage}).
 *
 * <p>One root cause, one error: a prerequisite broken again by later blocks (a program that never
 * starts the spindle) is reported at its first block, with a note that counts the later ones.
 * <p>Block delete: once a '/' block appears, a second checker follows the program with the
 * switch in the other position, so both variants are checked; what only the other finds is
 * reported with a note saying so.
 */
public final class Checker {
    /** After this many errors the checker reports E116 once and stops. */
    public static final int ERROR_CAP = 10_000;
    /** Prerequisite errors that later blocks repeat until the program fixes the cause. */
    private static final Set<Code> ROOT_CAUSES = Set.of(Code.E037_SPINDLE_DIRECTION_BEFORE_CUT,
            Code.E038_CHUCK_OPEN_CUT, Code.E039_FEED_NOT_SET, Code.E041_G50_NOT_SET_BEFORE_CUT,
            Code.E050_S_BEFORE_G50, Code.E051_SPINDLE_DIRECTION, Code.E103_FEED_ABOVE_MAXIMUM,
            Code.E104_FEED_PER_REV_NO_SPEED);
    private static final int NOTE_LINES = 5;

    private final Tables tables;
    private final MachineProfile profile;
    private final Diagnostics out;
    private final FunctionIndex functions;
    private final SyntaxActions actions = new SyntaxActions();
    private final Coordinates coordinates;
    private final MotionBuilder motions;
    private final int errorCap;
    /** One block's findings before they are reported (reused: nothing allocated per block). */
    private final Diagnostics scratch = new Diagnostics();
    private final Map<Code, Cause> causes = new EnumMap<>(Code.class);
    /** M codes already warned about (E113), N numbers seen (E114, controls where N may repeat). */
    private final BitSet warnedM = new BitSet();
    private final BitSet seenN = new BitSet();
    /** The block delete switch as this checker follows the program: true = '/' blocks are skipped. */
    private final boolean skipDeleted;
    /** The other position of the switch, from the first '/' block on; null before (and in the other itself). */
    private Checker other;
    private final boolean isOther;
    private ModalState state;
    /** The cycles (G70-G73, G90/G94): the contour read ahead, the stored contours, the expansion. */
    private final CycleExpansion cycles;
    /** Findings of contour blocks read ahead, so that following them again (G70) does not repeat them. */
    private final Set<String> aside = new HashSet<>();
    private long blocks;
    private boolean stopped;
    /** G41/G42: the compensated path, and what it needs to know of each block the flow made. */
    private NoseCompensation nose;
    private final Map<CheckedBlock, NoseCompensation.Info> noseInfo = new java.util.IdentityHashMap<>();

    /** A root cause already reported, and the later blocks that broke the same rule. */
    private static final class Cause {
        final Diagnostic first;
        int later;
        final StringBuilder lines = new StringBuilder();

        Cause(Diagnostic first) {
            this.first = first;
        }
    }

    public Checker(Tables tables, MachineProfile profile, Diagnostics out) {
        this(tables, profile, out, ERROR_CAP);
    }

    Checker(Tables tables, MachineProfile profile, Diagnostics out, int errorCap) {
        this(tables, profile, out, errorCap, profile.control().blockDelete() == Control.BlockDelete.ON, false);
    }

    private Checker(Tables tables, MachineProfile profile, Diagnostics out, int errorCap, boolean skipDeleted,
                    boolean isOther) {
        this.tables = tables;
        this.profile = profile;
        this.out = out;
        this.functions = new FunctionIndex(tables, profile.control());
        this.coordinates = new Coordinates(profile);
        this.motions = new MotionBuilder(profile, coordinates);
        this.errorCap = errorCap;
        this.skipDeleted = skipDeleted;
        this.isOther = isOther;
        this.state = ModalState.initial(profile);
        this.cycles = new CycleExpansion(this);
        this.nose = new NoseCompensation(profile, out);
    }

    /** The modal state after the last accepted block. */
    public ModalState state() {
        return state;
    }

    /**
     * Checks the next block as the program gives it. Usually one checked block or none; none while
     * a G71/G72/G73's contour is being read ahead, and the whole expanded cycle at its last block;
     * a G90/G94 block gives its moves.
     */
    public List<CheckedBlock> check(RawBlock b) {
        List<CheckedBlock> made = checkBlock(b);
        if (noseInfo.isEmpty() && !nose.active()) {
            return made; // no G41/G42 before or in these blocks: nothing to offset, nothing held
        }
        List<CheckedBlock> emit = new java.util.ArrayList<>(made.size() + 1);
        for (CheckedBlock c : made) {
            NoseCompensation.Info info = noseInfo.get(c);
            nose.accept(c, info != null ? info : new NoseCompensation.Info(NoseSide.OFF,
                    profile.nose(state.toolOffset()), state.toolOffset(), Span.of(c.line(), 1)), emit);
        }
        noseInfo.clear();
        if (state.ended()) {
            nose.end(b.words().isEmpty() ? b.last() : b.words().get(0).span(), emit);
        }
        return emit;
    }

    private List<CheckedBlock> checkBlock(RawBlock b) {
        if (stopped) {
            return List.of();
        }
        Span first = b.words().isEmpty() ? b.last() : b.words().get(0).span();
        if (out.errorCount() >= errorCap) {
            out.error(Code.E116_ERROR_CAP, first, out.errorCount());
            stopped = true;
            return List.of();
        }
        if (b.blockDelete() > 0) {
            if (profile.control().blockDelete() == Control.BlockDelete.NONE) {
                blocks++;
                out.error(Code.E010_SYNTAX, Span.of(b.line(), Math.max(1, first.column() - 1)), "'/'");
                return List.of();
            }
            if (other == null && !isOther) {
                other = fork();
            }
        }
        if (other != null) {
            other.check(b);
        }
        if (b.blockDelete() > 0 && skipDeleted) {
            return List.of();
        }
        boolean isFirst = blocks++ == 0;
        if (state.ended()) {
            out.error(Code.E053_M30_NOT_LAST, first);
            return List.of();
        }
        return flow(b, isFirst);
    }

    /** A counted block in the program's flow: part of a contour being read, a cycle, or a block. */
    List<CheckedBlock> flow(RawBlock b, boolean isFirst) {
        if (cycles.reading()) {
            return cycles.read(b);
        }
        if (b.macro() != null) {
            // a macro statement is run by gcnc.flow; one reaching the checker was not followed
            out.error(Code.E111_MACRO_NOT_SUPPORTED_YET, b.last(), b.macro().strip());
            return List.of();
        }
        if (b.malformed()) {
            state = Salvage.keep(b, state, functions, profile);
            return List.of();
        }
        // the compensation in force, or the one the block turns on ("G42"); null when neither
        boolean inForce = state.nose() != NoseSide.OFF;
        String compensation = inForce ? state.nose().g() : NoseConflict.turningOn(b, functions);
        Word conflict = compensation == null ? null : NoseConflict.find(b, functions, inForce);
        if (conflict != null) {
            out.error(Code.E178_NOSE_FUNCTION_IN_FORCE, conflict.span(), conflict, compensation);
            return List.of();
        }
        Word cycle = cycles.cycleWord(b);
        if (cycle != null) {
            return cycles.start(b, cycle, isFirst);
        }
        if (cycles.repeats(b)) {
            if (compensation != null) {
                // a modal cycle (G90/G94, G92, G32, G81-G83) would run again: not under compensation
                out.error(Code.E178_NOSE_FUNCTION_IN_FORCE, b.words().get(0).span(),
                        gcnc.diag.Phrase.CYCLE_AGAIN.with(cycles.repeating(b)), compensation);
                return List.of();
            }
            return cycles.repeat(b, isFirst);
        }
        cycles.note(b);
        return one(b, isFirst, null).map(List::of).orElse(List.of());
    }

    /**
     * One block through every check, committing its state: a block of the program, or one that a
     * cycle made or follows again ({@code origin} not null: its findings get a note saying which
     * pass, and its frame names the pass for the simulator's findings).
     */
    Optional<CheckedBlock> one(RawBlock b, boolean isFirst, CycleOrigin origin) {
        return one(b, isFirst, origin, null, null);
    }

    /**
     * A thread pass written as a G01 block (its F the lead per revolution), checked like any cut
     * and built as a spindle-synchronised {@link gcnc.ir.Motion.Thread}; {@code thread} names the
     * function ("G32", "G76") for its findings; {@code pullOut}, when not null, ends it with Haas
     * M23's chamfer instead of at the block's end point.
     */
    Optional<CheckedBlock> thread(RawBlock b, boolean isFirst, CycleOrigin origin, String thread, PullOut pullOut) {
        return thread(b, isFirst, origin, thread, pullOut, 0);
    }

    /** As above, the pass starting {@code startAngle} degrees past the spindle's whole revolution (Q of G92, Haas G76). */
    Optional<CheckedBlock> thread(RawBlock b, boolean isFirst, CycleOrigin origin, String thread, PullOut pullOut,
                                  double startAngle) {
        return one(b, isFirst, origin, thread, pullOut, startAngle);
    }

    private Optional<CheckedBlock> one(RawBlock b, boolean isFirst, CycleOrigin origin, String thread,
                                       PullOut pullOut) {
        return one(b, isFirst, origin, thread, pullOut, 0);
    }

    private Optional<CheckedBlock> one(RawBlock b, boolean isFirst, CycleOrigin origin, String thread,
                                       PullOut pullOut, double startAngle) {
        BlockDraft d = new BlockDraft(b, state, tables, functions, profile, coordinates, isFirst);
        d.thread = thread;
        d.pullOut = pullOut;
        d.startAngle = startAngle;
        scratch.clear();
        CheckedBlock result = run(d, scratch, true);
        report(b, origin);
        boolean sequence = origin == null || !origin.again();
        if (result == null) {
            recover(b, isFirst, sequence);
            return Optional.empty();
        }
        commit(d, sequence);
        if (!causes.isEmpty() && cuts(result)) {
            closeCauses();
        }
        if (out.place() != gcnc.diag.Origin.PROGRAM) {
            result = result.from(out.place()); // a called program's block: the simulator places its findings there
        }
        CheckedBlock made = origin == null ? result : origin.label(result);
        if (state.nose() != NoseSide.OFF || d.prior.nose() != NoseSide.OFF) {
            // a block without this record has G40 in force before and after it (most blocks: nothing allocated)
            noseInfo.put(made, new NoseCompensation.Info(state.nose(), profile.nose(state.toolOffset()),
                    state.toolOffset(), b.words().isEmpty() ? b.last() : b.words().get(0).span()));
        }
        return Optional.of(made);
    }

    /** What a block would do from {@code from}, checked but not committed, or null after its errors. */
    record Dry(CheckedBlock block, ModalState next) {
    }

    /**
     * A contour block followed from {@code from} without changing the program's state: its words
     * and geometry checked (not the prerequisites: the cycle's own moves are checked for those),
     * findings to {@code found}.
     */
    Dry dry(RawBlock b, ModalState from, Diagnostics found) {
        BlockDraft d = new BlockDraft(b, from, tables, functions, profile, coordinates, false);
        CheckedBlock r = run(d, found, false);
        if (r == null) {
            return null;
        }
        noteSequence(d);
        return new Dry(r, d.next.build());
    }

    /** Reports findings of a block checked outside the flow (a contour read ahead), remembering them. */
    void reportAside(Diagnostics found) {
        for (Diagnostic diag : found.sorted()) {
            if (aside.add(key(diag))) {
                out.report(diag);
            }
        }
    }

    Diagnostics out() {
        return out;
    }

    FunctionIndex functions() {
        return functions;
    }

    MachineProfile profile() {
        return profile;
    }

    Coordinates coordinates() {
        return coordinates;
    }

    /** The checker for the other position of the block delete switch, from the state reached so far. */
    private Checker fork() {
        Checker c = new Checker(tables, profile, out.sibling(), errorCap, !skipDeleted, true);
        c.state = state;
        c.nose = nose.copy(c.out);
        c.blocks = blocks;
        c.seenN.or(seenN);
        c.warnedM.or(warnedM);
        return c;
    }

    /**
     * Reports the block's findings, folding a repeated root cause into its first report; a block
     * of a cycle adds a note naming its pass, and a contour block followed again (G70) does not
     * repeat what reading it ahead already reported.
     */
    private void report(RawBlock b, CycleOrigin origin) {
        if (scratch.size() == 0) {
            return;
        }
        for (Diagnostic diag : scratch.sorted()) {
            if (origin != null && origin.again() && aside.contains(key(diag))) {
                continue;
            }
            Cause c = causes.get(diag.code());
            if (c != null && diag.severity() == Severity.ERROR) {
                c.later++;
                if (c.later <= NOTE_LINES) {
                    c.lines.append(c.lines.length() == 0 ? "" : ", ").append(b.line());
                } else if (c.later == NOTE_LINES + 1) {
                    c.lines.append(", ...");
                }
                continue;
            }
            if (ROOT_CAUSES.contains(diag.code())) {
                causes.put(diag.code(), new Cause(diag));
            }
            out.report(diag);
            if (origin != null && origin.noted() && diag.severity() != Severity.NOTE) {
                out.report(origin.note(diag.span()));
            }
        }
    }

    private static boolean cuts(CheckedBlock b) {
        for (gcnc.ir.Motion m : b.motions()) {
            if (m.accept(CUTS)) {
                return true;
            }
        }
        return false;
    }

    /** Whether a motion cuts: a feed, an arc or a thread pass. */
    private static final gcnc.ir.Motion.Visitor<Boolean> CUTS = new gcnc.ir.Motion.Visitor<>() {
        @Override
        public Boolean linear(gcnc.ir.Motion.Linear l) {
            return !l.rapid();
        }

        @Override
        public Boolean arc(gcnc.ir.Motion.Arc a) {
            return true;
        }

        @Override
        public Boolean dwell(gcnc.ir.Motion.Dwell d) {
            return false;
        }

        @Override
        public Boolean thread(gcnc.ir.Motion.Thread t) {
            return true;
        }
    };

    /** A clean cut: every prerequisite holds again, so a later break is a new cause. */
    private void closeCauses() {
        if (causes.isEmpty()) {
            return;
        }
        for (Cause c : causes.values()) {
            note(c);
        }
        causes.clear();
    }

    private void note(Cause c) {
        if (c.later > 0) {
            out.report(new Diagnostic(Code.E115_SAME_CAUSE, Severity.NOTE, c.first.span(),
                    List.of(Integer.toString(c.later), c.lines.toString()), c.first.origin().withoutCalls()));
        }
    }

    /**
     * Takes the block's next state, with its warnings: M codes without output (E113), a repeated N
     * (E114; not for a contour block followed again by G70: {@code sequence} false).
     */
    private void commit(BlockDraft d, boolean sequence) {
        for (Word w : d.unpowered()) {
            int m = (int) w.code();
            if (!warnedM.get(m)) {
                warnedM.set(m);
                out.report(Diagnostic.warning(Code.E113_M_WITHOUT_OUTPUT, w.span(), m, profile.name()));
            }
        }
        if (sequence) {
            noteSequence(d);
        }
        state = d.next.build();
    }

    /** A repeated N (E114) where N may repeat; remembers the block's N. */
    private void noteSequence(BlockDraft d) {
        if (d.has(gcnc.ir.Letter.N) && !profile.control().increasingN() && d.block.depth() == 0) {
            long n = (long) d.value(gcnc.ir.Letter.N);
            if (n >= 0 && n < Integer.MAX_VALUE) {
                if (seenN.get((int) n)) {
                    Word w = d.word(gcnc.ir.Letter.N);
                    out.report(Diagnostic.warning(Code.E114_DUPLICATE_SEQUENCE_NUMBER, w.span(), w.number()));
                }
                seenN.set((int) n);
            }
        }
    }

    /**
     * After an error: if the block is clean but for prerequisite rules (an F, M11, M03 or G50 S
     * missing before a cut, an S above the clamp), take the state it would have left, as if the
     * programmer had fixed what was reported. Otherwise its F, G01, S or M03 would be lost and
     * every later block would report an echo of this one instead of its own errors. The re-run
     * reports nothing. A block with any other error keeps only its unambiguous modal words.
     */
    private void recover(RawBlock b, boolean isFirst, boolean sequence) {
        BlockDraft d = new BlockDraft(b, state, tables, functions, profile, coordinates, isFirst);
        if (run(d, new Diagnostics(), false) != null) {
            commit(d, sequence);
        } else {
            state = Salvage.keep(b, state, functions, profile);
        }
    }

    private CheckedBlock run(BlockDraft d, Diagnostics out, boolean prerequisites) {
        Word unsupported = d.unsupported;
        if (unsupported != null) {
            actions.action(17).apply(unsupported, d, out);
            return null;
        }
        List<Word> words = d.block.words();
        for (int i = 0; i < words.size() && !d.failed(); i++) {
            Word w = words.get(i);
            SyntaxAction a = actions.lookUp(w, d, out);
            if (a != null) {
                a.apply(w, d, out);
            }
        }
        for (int i = 0; i < BlockChecks.ORDER.size() && !d.failed(); i++) {
            BlockCheck c = BlockChecks.ORDER.get(i);
            if (prerequisites || !c.prerequisite()) {
                c.run(d, out);
            }
        }
        return d.failed() ? null : motions.build(d, out);
    }

    /** End of the program: it must have ended (52: M30, or what the control's table says ends one). */
    public void finish(int lastLine) {
        cycles.finish();
        if (nose.active()) {
            nose.end(Span.of(Math.max(1, lastLine), 1), new java.util.ArrayList<>()); // nothing can be sent after the end
        }
        for (Cause c : causes.values()) {
            note(c);
        }
        causes.clear();
        if (!stopped && !state.ended()) {
            out.error(Code.E052_NO_M30, Span.of(Math.max(1, lastLine), 1), profile.control().endCodes());
        }
        if (other != null) {
            other.finish(lastLine);
            merge(other.out, !skipDeleted);
        }
    }

    /** Adds what only the other position of the block delete switch found, each with a note saying so. */
    private void merge(Diagnostics found, boolean switchOn) {
        Set<String> mine = new HashSet<>();
        for (Diagnostic d : out.sorted()) {
            mine.add(key(d));
        }
        for (Diagnostic d : found.sorted()) {
            if (mine.add(key(d))) {
                out.report(d);
                if (d.severity() != Severity.NOTE) {
                    out.report(new Diagnostic(Code.E118_BLOCK_DELETE_VARIANT, Severity.NOTE, d.span(),
                            List.of(switchOn ? "on" : "off"), d.origin().withoutCalls()));
                }
            }
        }
    }

    private static String key(Diagnostic d) {
        return d.code() + "@" + d.origin().file() + ":" + d.span() + d.args();
    }
}
