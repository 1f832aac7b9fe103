package gcnc.dmc;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.machine.ControllerLimits;
import gcnc.machine.GalilModel.Limit;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * Puts a compiled program in the form it is downloaded in (docs/galil.md, "Two forms"): the
 * program form when it fits the model's program memory, the stream form otherwise, or the form
 * asked for ({@code --form}). The instructions come in the program form's order; {@code dmc}
 * receives the program's packed lines (program form) or, at {@link #finish}, the resident program's
 * (stream form); {@code stream} receives the segment stream as it comes.
 *
 * <p>Lines are counted packed ({@link LinePacker}), as the program form is written.
 *
 * <p>Look-ahead, with no form asked: the instructions of the first program-memory-full of packed
 * lines (2,000 or 4,000 per the model, at most 40 commands a line) are held; one line more and the
 * program goes to the stream form.
 */
public final class FormChoice implements Consumer<Instruction> {
    private final Optional<Form> asked;
    private final ControllerLimits limits;
    private final Consumer<LinePacker.Line> dmc;
    private final Consumer<Instruction> stream;
    private final long memory;
    private final int width;
    /** Packs the program form; each line is printed once, here. */
    private final LinePacker packer;
    /** The program form's lines held until it is known to fit (no form asked). */
    private final List<LinePacker.Line> held = new ArrayList<>();
    /** The stream form being written; null while the program form is. */
    private StreamSplit split;
    /** With the program form asked: the stream form counted beside it, to say in E238 what would fit. */
    private StreamSplit counted;
    private long lines;

    /**
     * @param dmc    receives the DMC's packed lines: the program form's as they come (program asked)
     *               or once it is known to fit, or the resident program's at {@link #finish}
     * @param stream receives the segment stream, a command at a time
     */
    public FormChoice(Optional<Form> asked, ControllerLimits limits, Consumer<LinePacker.Line> dmc,
                      Consumer<Instruction> stream) {
        this.asked = asked;
        this.limits = limits;
        this.dmc = dmc;
        this.stream = stream;
        this.memory = limits.model().range(Limit.PROGRAM_LINES).max();
        this.width = limits.lineWidth();
        this.packer = new LinePacker(width, this::line);
        if (asked.equals(Optional.of(Form.STREAM))) {
            split = new StreamSplit(stream, memory, width);
        } else if (asked.equals(Optional.of(Form.PROGRAM))) {
            counted = new StreamSplit(i -> { }, memory, width);
        }
    }

    @Override
    public void accept(Instruction i) {
        if (split != null) {
            split.accept(i);
            return;
        }
        packer.accept(i);
        if (counted != null) {
            counted.accept(i);
        } else if (lines > memory) {
            toStream();
        }
    }

    /** A line of the program form: written (program asked), or held until the program is known to fit. */
    private void line(LinePacker.Line l) {
        lines++;
        if (counted != null) {
            dmc.accept(l);
        } else {
            held.add(l);
        }
    }

    /** Longer than the memory: the stream form, from the first instruction (the line being filled too). */
    private void toStream() {
        packer.flush();
        split = new StreamSplit(stream, memory, width);
        for (LinePacker.Line l : held) {
            l.instructions().forEach(split);
        }
        held.clear();
    }

    /**
     * The form the program was written in, once its last instruction passed: the resident program
     * goes to {@code dmc} now (stream form), and what does not fit is reported: the program form
     * asked for and too long (E238, naming the stream form's size), a resident program too long
     * (E239) or with too many labels (E229), a block that must run inside the controller and is too
     * long for one routine (E243). Reported at line 1 of the program, or at the block.
     */
    public Form finish(Diagnostics diagnostics) {
        Span first = Span.of(1, 1);
        if (split == null) {
            packer.flush();
        }
        if (split == null && counted == null && lines > memory) {
            toStream(); // the last line was the one too many
        }
        if (split == null) {
            held.forEach(dmc);
            held.clear();
            if (counted != null && lines > memory) {
                StreamSplit.Result s = counted.finish();
                diagnostics.report(Diagnostic.error(Code.E238_PROGRAM_DOES_NOT_FIT, first, lines, memory,
                        limits.model().name(), s.residentLines(), s.streamLines()));
            }
            return Form.PROGRAM;
        }
        StreamSplit.Result s = split.finish();
        for (Source at : s.tooLong()) {
            Diagnostic d = Diagnostic.error(Code.E243_BLOCK_TOO_LONG_TO_EMBED, Span.of(Math.max(1, at.line()), 1),
                    StreamSplit.RUN_LIMIT);
            diagnostics.report(at.line() > 0 ? d.in(at.origin()) : d);
        }
        if (s.residentLines() > memory) {
            diagnostics.report(Diagnostic.error(Code.E239_RESIDENT_DOES_NOT_FIT, first, s.residentLines(), memory,
                    limits.model().name(), s.moved()));
        } else {
            limits.check(Limit.LABELS, s.residentLabels()).ifPresent(v -> diagnostics.report(v.diagnostic(first)));
        }
        LinePacker.pack(s.resident(), width).forEach(dmc);
        return Form.STREAM;
    }
}
