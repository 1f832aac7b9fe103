package gcnc.check;

import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Phrase;
import gcnc.diag.Span;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Reads a thread block's words (G32, G92, G76) into the values its passes are planned from: the
 * lead, lengths in program units, a start angle, a Fanuc depth in least increments, and where the
 * axis words lead. Each error is reported here, and the value is NaN (or null) after it.
 */
final class ThreadValues {
    private final CycleHost host;

    ThreadValues(CycleHost host) {
        this.host = host;
    }

    /** The block's X/U/Z/W words in the order written. */
    static List<Word> axes(Map<Letter, Word> words) {
        List<Word> axes = new ArrayList<>(2);
        for (Letter l : new Letter[] {Letter.X, Letter.U, Letter.Z, Letter.W}) {
            if (words.containsKey(l)) {
                axes.add(words.get(l));
            }
        }
        axes.sort((p, q) -> Integer.compare(p.span().column(), q.span().column()));
        return axes;
    }

    /** The lead: the block's F, else the F in force; NaN after reporting E195 or E198. */
    double lead(Map<Letter, Word> words, String label, Span at) {
        Word f = words.get(Letter.F);
        double lead = f != null ? NumberText.decimal(f.number()) : host.state().feed();
        if (f != null && Double.isNaN(lead)) {
            host.out().error(Code.E014_DECIMAL_EXPECTED, f.span(), Letter.F);
            return Double.NaN;
        }
        if (Double.isNaN(lead)) {
            host.out().error(Code.E195_THREAD_WORD_MISSING, at, label, Phrase.THREAD_LEAD.arg());
            return Double.NaN;
        }
        if (!(lead > 0)) {
            host.out().error(Code.E198_THREAD_LEAD, f != null ? f.span() : at, label, NumberText.plain(lead));
            return Double.NaN;
        }
        return lead;
    }

    /** A length word in program units, radius (no-point rule of the control when written without a point), or NaN after E014. */
    double length(Word w) {
        double v = NumberText.decimal(w.number());
        if (Double.isNaN(v)) {
            host.out().error(Code.E014_DECIMAL_EXPECTED, w.span(), w.letter());
            return Double.NaN;
        }
        if (!NumberText.hasPoint(w.number())) {
            v *= host.state().units() == Units.INCH ? host.profile().noPointInch() : host.profile().noPointMm();
        }
        return v;
    }

    /** A start angle Q in degrees (ThreadWords.startAngle); NaN after E197. */
    double startAngle(Word w, String label) {
        double v = ThreadWords.startAngle(w.number());
        if (Double.isNaN(v)) {
            host.out().error(Code.E197_THREAD_WORD_VALUE, w.span(), label, w, Phrase.THREAD_START_ANGLE.arg());
        }
        return v;
    }

    /** A Fanuc G76 P/Q depth: a whole number of least increments, without a point; NaN after E197. */
    double increments(Word w, String label) {
        long n = NumberText.integer(w.number());
        if (NumberText.hasPoint(w.number()) || n == NumberText.NOT_INTEGER) {
            host.out().error(Code.E197_THREAD_WORD_VALUE, w.span(), label, w,
                    Phrase.THREAD_LEAST_INCREMENTS.arg());
            return Double.NaN;
        }
        return n * (host.state().units() == Units.INCH ? 0.0001 : 0.001);
    }

    /** Where the axis words lead from the start (followed aside as a rapid), or null after their error. */
    Point target(RawBlock b, List<Word> axes) {
        List<Word> ws = new ArrayList<>(axes.size() + 1);
        String rapid = host.profile().control().gFor(GRole.RAPID).map(f -> f.name().substring(1)).orElseThrow();
        ws.add(new Word(Letter.G, rapid, axes.get(0).span()));
        ws.addAll(axes);
        Diagnostics found = new Diagnostics();
        Dry dry = host.dry(new RawBlock(b.line(), ws, ws.get(ws.size() - 1).span(), false), host.state(),
                found);
        host.out().addAll(found);
        return dry == null ? null : dry.block().end();
    }
}
