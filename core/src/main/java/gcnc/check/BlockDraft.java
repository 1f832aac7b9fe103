package gcnc.check;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.Letter;
import gcnc.ir.MCall;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import gcnc.tables.Tables;
import java.util.ArrayList;
import java.util.List;

/**
 * One block while it is being checked: the words each syntax action accepted, the block's
 * functions, and the next modal state. Dropped when the block has an error.
 *
 * <p>A checker has one draft and {@link #start starts} it afresh for each block it checks (the
 * program's, a contour's read ahead, a re-run after an error): a block is checked from start to
 * commit before the next one starts, and nothing keeps a draft, or its {@link #next}, beyond its
 * block. The draft, its next state and its word arrays were the largest allocations per block
 * (bench/HISTORY.md, issue 23). {@link #start} sets every field below the context fields.
 */
public final class BlockDraft {
    public static final int NONE = -1;
    private static final int GROUPS = 20;

    /** The checker's context, the same for every block. */
    public final Tables tables;
    public final FunctionIndex functions;
    public final MachineProfile profile;
    public final gcnc.check.geom.Coordinates coordinates;

    /** The block (set by {@link #start}, like the fields after it; read-only to the actions and checks). */
    public RawBlock block;
    public ModalState prior;
    /** The state the block leaves, from {@link #prior}; the checker builds it when it commits the block. */
    public final ModalState.Next next = new ModalState.Next();
    /** Units of the whole block: a G20/G21 anywhere in it (thesis applied them per word, §12.12). */
    public Units units;
    /** No block was counted before this one (O must come first: error 34). */
    public boolean first;

    /**
     * The accepted words and their values, in the order accepted, and which letters they are (bit =
     * letter ordinal): a block has a handful of words, so these are sized by the block rather than
     * by the alphabet, and a letter is found by a short scan (a checker allocated two 26-slot arrays
     * per block before). The 26 letters fit the bits of one int.
     */
    private Word[] words;
    private double[] values;
    private int count;
    private int letters;
    /** The words that claimed a modal group, and which (G group g as g, M group g as GROUPS + g). */
    private Word[] claims;
    private int[] claimed;
    private int claimCount;

    /** The block's motion G (group 1) or NONE, by thesis number (0-3). */
    public int motionG = NONE;
    /** The word that set motionG, or null. */
    public Word motionWord;
    /** The block's one-shot G with parameters (4, 28, 29, 50, 53, 92 by thesis number) or NONE (thesis GWP). */
    public int oneShot = NONE;
    public Word oneShotWord;
    /** The function the block's parameters belong to (thesis nf), decided by Eb01. */
    public int function = NONE;
    /** The spindle M (3, 4, 19) applied before this block's motion, or NONE. */
    public int spindleBefore = NONE;
    /** The block's G96 word (its S is then a surface speed), or null. */
    public Word g96;
    /** G09 in the block: its motion ends at rest, whatever the mode (Sa11). */
    public boolean exactStop;
    private List<MCall> before;
    /** M words whose function needs an output that the machine profile does not give (E113). */
    private List<Word> unpowered;
    private List<MCall> after;
    /**
     * The block is a thread pass written as G01 (G32/G33, a pass of G92/G78 or G76), named here
     * ("G76"): its F is the lead per revolution and its move is spindle-synchronised; null otherwise.
     */
    public String thread;
    /**
     * The thread pass ends with Haas M23's chamfered pull-out (a pass of G76 or G92): the chamfer
     * and which way X goes out; null for a square end (M24, G32) and for every other block.
     */
    public PullOut pullOut;
    /** The spindle angle a thread pass starts at, degrees (a multi-start thread's G92/Haas G76 Q); 0 otherwise. */
    public double startAngle;
    /**
     * The block's first G or M word whose function gcnc cannot follow yet (a G whose role is
     * unsupported, an M that is unsupported or a call the flow stage did not take), or null: the
     * checker reports it before anything else in the block (at the G71, not at its later P or Q).
     * Found in the same pass over the words as the block's units.
     */
    public Word unsupported;
    private boolean failed;

    /** A checker's draft; {@link #start} gives it each block. */
    BlockDraft(Tables tables, FunctionIndex functions, MachineProfile profile,
               gcnc.check.geom.Coordinates coordinates) {
        this.tables = tables;
        this.functions = functions;
        this.profile = profile;
        this.coordinates = coordinates;
    }

    /** This draft, emptied and set to check {@code block} from {@code prior}. */
    BlockDraft start(RawBlock block, ModalState prior, boolean first) {
        this.block = block;
        this.prior = prior;
        next.load(prior);
        this.first = first;
        if (words != null) {
            java.util.Arrays.fill(words, 0, count, null); // the last block's words are not kept alive
        }
        if (claims != null) {
            java.util.Arrays.fill(claims, 0, claimCount, null);
        }
        count = 0;
        letters = 0;
        claimCount = 0;
        motionG = NONE;
        motionWord = null;
        oneShot = NONE;
        oneShotWord = null;
        function = NONE;
        spindleBefore = NONE;
        g96 = null;
        exactStop = false;
        before = null;
        unpowered = null;
        after = null;
        thread = null;
        pullOut = null;
        startAngle = 0;
        failed = false;
        Units u = prior.units();
        Word notYet = null;
        List<Word> ws = block.words();
        for (int i = 0; i < ws.size(); i++) {
            Word w = ws.get(i);
            if (w.letter() == Letter.G) {
                GFunction f = functions.g(w.code());
                if (f != null && f.role() == GRole.INCH) {
                    u = Units.INCH;
                } else if (f != null && f.role() == GRole.METRIC) {
                    u = Units.MM;
                } else if (f != null && notYet == null && f.role().unsupported() && !w.number().isEmpty()) {
                    notYet = w;
                }
            } else if (w.letter() == Letter.M && notYet == null && !w.number().isEmpty()) {
                gcnc.machine.MFunction f = functions.m(w.code());
                if (f != null && (f.role() == gcnc.machine.MRole.UNSUPPORTED || f.role().call())) {
                    notYet = w;
                }
            }
        }
        this.units = u;
        this.unsupported = notYet;
        next.units = units;
        return this;
    }

    /** The G function whose parameters the block's words are (Eb01), or null. */
    public GFunction owner() {
        if (oneShotWord != null) {
            return functions.g(oneShotWord.code());
        }
        if (motionWord != null) {
            return functions.g(motionWord.code());
        }
        return function >= 0 && function <= 3 ? functions.g(GRole.values()[function]) : null;
    }

    /** The owner function as the program wrote it ("G92" on Fanuc B, whose thesis number is 50). */
    public String ownerName() {
        GFunction f = owner();
        return f != null ? f.name() : "G" + function;
    }

    /**
     * An M function of the block, applied at the start (moments 0 and 1) or at the end (99), in
     * source order. (Most blocks have none: the lists are made by the first.)
     */
    public void addM(MCall m, boolean beforeMotion) {
        if (beforeMotion) {
            if (before == null) {
                before = new ArrayList<>(2);
            }
            before.add(m);
        } else {
            if (after == null) {
                after = new ArrayList<>(2);
            }
            after.add(m);
        }
    }

    /** The M functions applied before the block's motion, in source order. */
    public List<MCall> before() {
        return before == null ? List.of() : before;
    }

    /** The M functions applied after it. */
    public List<MCall> after() {
        return after == null ? List.of() : after;
    }

    /** M words whose function needs an output that the machine profile does not give (E113). */
    public List<Word> unpowered() {
        return unpowered == null ? List.of() : unpowered;
    }

    /** Notes an M word that does nothing on this machine: it needs an output the profile lacks. */
    public void unpoweredM(gcnc.machine.MFunction f, Word w) {
        if (f.needsOutput() && profile.outputsFor(f.code()).isEmpty()) {
            if (unpowered == null) {
                unpowered = new ArrayList<>(2);
            }
            unpowered.add(w);
        }
    }

    /** Reports the block's first error; the checker stops working on the block after it. */
    public void fail(Diagnostics out, Code code, Span where, Object... args) {
        if (!failed) {
            out.error(code, where, args);
            failed = true;
        }
    }

    public boolean failed() {
        return failed;
    }

    public Word word(Letter l) {
        int i = slot(l);
        return i < 0 ? null : words[i];
    }

    public boolean has(Letter l) {
        return (letters & 1 << l.ordinal()) != 0;
    }

    /** The value of an accepted word: coordinates after the no-point rule, others as written (0 when none). */
    public double value(Letter l) {
        int i = slot(l);
        return i < 0 ? 0 : values[i];
    }

    /** Where letter l's accepted word is kept, or -1. */
    private int slot(Letter l) {
        if (!has(l)) {
            return -1;
        }
        for (int i = 0; i < count; i++) {
            if (words[i].letter() == l) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Whether a parameter word may be read (actions 2 and 4): not already in the block (E007) and
     * with a number (E006; the parser reports bare letters first, this guards the contract).
     */
    public boolean fresh(Word w, Diagnostics out) {
        if (has(w.letter())) {
            fail(out, Code.E007_DUPLICATE_PARAMETER, w.span(), w.letter());
            return false;
        }
        if (w.number().isEmpty()) {
            fail(out, Code.E006_NUMBER_EXPECTED, w.span(), w.letter());
            return false;
        }
        return true;
    }

    public void accept(Word w, double value) {
        int i = slot(w.letter());
        if (i < 0) {
            if (words == null) {
                int n = Math.max(8, block.words().size());
                words = new Word[n];
                values = new double[n];
            } else if (count == words.length) {
                words = java.util.Arrays.copyOf(words, 2 * count);
                values = java.util.Arrays.copyOf(values, 2 * count);
            }
            i = count++;
            letters |= 1 << w.letter().ordinal();
        }
        words[i] = w;
        values[i] = value;
    }

    /**
     * Claims a G function's modal group for this block: false, after reporting E016 with the G
     * that holds it, when another G of the group came first (thesis §12.19: every group, not only 1).
     */
    public boolean claimG(int group, Word w, Diagnostics out) {
        return group < 0 || group >= GROUPS || claim(group, w, out);
    }

    /** The same for an M function's group (group 0, no group, never conflicts). */
    public boolean claimM(int group, Word w, Diagnostics out) {
        return group <= 0 || group >= GROUPS || claim(GROUPS + group, w, out);
    }

    private boolean claim(int key, Word w, Diagnostics out) {
        for (int i = 0; i < claimCount; i++) {
            if (claimed[i] == key) {
                fail(out, Code.E016_GROUP_CONFLICT, w.span(), claims[i]);
                return false;
            }
        }
        if (claims == null) {
            claims = new Word[4];
            claimed = new int[4];
        } else if (claimCount == claims.length) {
            claims = java.util.Arrays.copyOf(claims, 2 * claimCount);
            claimed = java.util.Arrays.copyOf(claimed, 2 * claimCount);
        }
        claims[claimCount] = w;
        claimed[claimCount++] = key;
        return true;
    }

    /** Number of axis and radius words (thesis "mov": X Z U W R I K). */
    public int motionWords() {
        int n = 0;
        for (Letter l : MOTION_WORDS) {
            if (has(l)) {
                n++;
            }
        }
        return n;
    }

    public static final Letter[] MOTION_WORDS = {Letter.X, Letter.Z, Letter.U, Letter.W, Letter.R, Letter.I, Letter.K};

    /** The first word of the block, where block-level errors such as 53 are reported. */
    public Span firstSpan() {
        return block.words().isEmpty() ? block.last() : block.words().get(0).span();
    }

    /**
     * The block's first axis or radius word (X Z U W R I K) in the order written, or null. A block
     * that moves under a modal G01 ({@code Z-10.}) is to blame there: it is the word that moves.
     */
    public Word firstMotionWord() {
        List<Word> ws = block.words();
        for (int i = 0; i < ws.size(); i++) {
            Word w = ws.get(i);
            for (Letter l : MOTION_WORDS) {
                if (w.letter() == l && word(l) == w) {
                    return w;
                }
            }
        }
        return null;
    }

    /**
     * Where an error about the block's motion goes (a cut before M03, an arc without R): at the
     * word that asks for the motion, its G01/G02/G03, else its first axis word. The thesis put
     * every end-of-block error at the last word (§10), which pointed a machinist at an innocent
     * F120. and not at the G01 that broke the rule.
     */
    public Span blame() {
        if (motionWord != null) {
            return motionWord.span();
        }
        Word w = firstMotionWord();
        return w != null ? w.span() : end();
    }

    /** The last word: where an end-of-block error goes when no word is to blame (thesis §10). */
    public Span end() {
        return block.last();
    }
}
