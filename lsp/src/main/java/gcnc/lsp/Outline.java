package gcnc.lsp;

import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;
import gcnc.parse.BlockReader;
import java.io.IOException;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;

/**
 * A buffer's blocks as gcnc's parser reads them (words with their spans, no program flow, findings
 * thrown away: the check reports them), and what the words mean for the editor's navigation and
 * symbols on this control: which block calls which program or sequence number, where each N is.
 */
final class Outline {
    /** What a P (or Q) word of a block points at. */
    enum Target {
        /** an O number: another program (M98, G65), in this file after its end or in a file of its own */
        PROGRAM,
        /** an N number in this file (M97, M99 P, a G70-G73 range's P and Q) */
        SEQUENCE
    }

    /** A P or Q word that names a program or a sequence number, with the number it names. */
    record Reference(Word word, Target target, long number, RawBlock block) {
    }

    private final List<RawBlock> blocks;
    private final Control control;

    private Outline(List<RawBlock> blocks, Control control) {
        this.blocks = blocks;
        this.control = control;
    }

    static Outline of(String text, Control control) {
        List<RawBlock> blocks = new ArrayList<>();
        try {
            BlockReader r = BlockReader.forControl(new StringReader(text), new Diagnostics(), control.macros(),
                    control.lineComments());
            for (RawBlock b = r.next(); b != null; b = r.next()) {
                blocks.add(b);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a StringReader does not fail
        }
        return new Outline(blocks, control);
    }

    List<RawBlock> blocks() {
        return blocks;
    }

    /** The word whose text covers 1-based {@code line} and {@code column} (or ends right before it). */
    Optional<Word> wordAt(int line, int column) {
        for (RawBlock b : blocks) {
            if (b.line() == line) {
                for (Word w : b.words()) {
                    int end = w.span().hasEnd() ? w.span().endColumn() : w.span().column() + 1 + w.number().length();
                    if (column >= w.span().column() && column <= end) {
                        return Optional.of(w);
                    }
                }
            }
            if (b.line() > line) {
                break;
            }
        }
        return Optional.empty();
    }

    /** The block of {@code line}, if the line has one. */
    Optional<RawBlock> blockAt(int line) {
        return blocks.stream().filter(b -> b.line() == line).findFirst();
    }

    /** The first block whose N word has {@code number}. */
    Optional<Word> sequence(long number) {
        for (RawBlock b : blocks) {
            for (Word w : b.words()) {
                if (w.letter() == Letter.N && digits(w) == number) {
                    return Optional.of(w);
                }
            }
        }
        return Optional.empty();
    }

    /** The O word that starts program {@code number} in this file (a subprogram after the main program's end). */
    Optional<Word> program(long number) {
        for (RawBlock b : blocks) {
            if (!b.words().isEmpty() && b.words().get(0).letter() == Letter.O && digits(b.words().get(0)) == number) {
                return Optional.of(b.words().get(0));
            }
        }
        return Optional.empty();
    }

    /** Every P and Q word of this buffer that names a program or a sequence number. */
    List<Reference> references() {
        List<Reference> out = new ArrayList<>();
        for (RawBlock b : blocks) {
            references(b, out);
        }
        return out;
    }

    /** The reference {@code word} is, if it is one. */
    Optional<Reference> reference(Word word) {
        return references().stream().filter(r -> r.word() == word).findFirst();
    }

    private void references(RawBlock b, List<Reference> out) {
        Target target = null;
        boolean range = false;
        boolean macroCall = false;
        for (Word w : b.words()) {
            if (w.letter() == Letter.M) {
                MFunction f = control.m().get((int) Math.min(Integer.MAX_VALUE, Math.max(-1, digits(w))));
                if (f != null && f.role() == MRole.CALL) {
                    target = Target.PROGRAM;
                } else if (f != null && (f.role() == MRole.LOCAL_CALL || f.role() == MRole.RETURN)) {
                    target = Target.SEQUENCE;
                }
            } else if (w.letter() == Letter.G) {
                long code = digits(w);
                GFunction g = code >= 0 && code < 1000 ? control.g().get((int) code) : null;
                if (g != null && g.role() == GRole.MACRO_CALL) {
                    target = Target.PROGRAM; // G65 P: the program number alone, as gcnc.flow reads it
                    macroCall = true;
                }
                if (g != null && rangeCycle(g.role())) {
                    range = true;
                }
            }
        }
        for (Word w : b.words()) {
            long n = digits(w);
            if (n < 0) {
                continue;
            }
            if (w.letter() == Letter.P && target == Target.PROGRAM) {
                boolean countInP = !macroCall && control.calls().countInP() && w.number().length() > 4;
                out.add(new Reference(w, Target.PROGRAM, countInP ? n % 10_000 : n, b));
            } else if (w.letter() == Letter.P && target == Target.SEQUENCE) {
                out.add(new Reference(w, Target.SEQUENCE, n, b));
            } else if ((w.letter() == Letter.P || w.letter() == Letter.Q) && range) {
                out.add(new Reference(w, Target.SEQUENCE, n, b));
            }
        }
    }

    /** G70-G73: the cycles whose P and Q name the first and last N of the profile. */
    static boolean rangeCycle(GRole role) {
        return role == GRole.FINISHING_CYCLE || role == GRole.TURNING_CYCLE || role == GRole.FACING_CYCLE
                || role == GRole.PATTERN_CYCLE;
    }

    /** The value of a word written with digits only (N100, P1000), else -1. */
    static long digits(Word w) {
        String s = w.number();
        if (s.isEmpty() || s.length() > 18) {
            return -1;
        }
        for (int i = 0; i < s.length(); i++) {
            if (s.charAt(i) < '0' || s.charAt(i) > '9') {
                return -1;
            }
        }
        return Long.parseLong(s);
    }

    /** The G function of a G word on this control, if it has one. */
    Optional<GFunction> g(Word w) {
        long code = w.letter() == Letter.G ? digits(w) : -1;
        return code >= 0 && code < 1000 ? Optional.ofNullable(control.g().get((int) code)) : Optional.empty();
    }

    /** The tool a T word selects (T0303: 3), if it is one. */
    static OptionalLong tool(Word w) {
        long t = w.letter() == Letter.T ? digits(w) : -1;
        if (t < 0) {
            return OptionalLong.empty();
        }
        return OptionalLong.of(w.number().length() > 2 ? t / 100 : t);
    }
}
