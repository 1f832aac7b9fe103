package gcnc.lsp;

import gcnc.flow.Library;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.SymbolKind;

/**
 * Go to definition, references and the outline of a buffer, from its {@link Outline}:
 * <ul>
 * <li>the P of {@code M98 P1000} / {@code G65 P1000} goes to program O1000: its O line in this file (a
 * subprogram after the main program's end), else the file beside it that the check would read
 * ({@link Library#fileFor}: O1000.nc, 1000.nc, ...); the P of {@code M97 P100} or {@code M99 P100}
 * and the P and Q of a G70-G73 range go to the block N100 of this file;</li>
 * <li>references of a sequence number (on its N word, or on a P or Q naming it): every P and Q of this
 * file that names it, and the N itself; of a program number, the calls of it in this file;</li>
 * <li>symbols: each program (its O line) holding the operations, one per tool change (the T word
 * and the line's comment), holding their canned cycles.</li>
 * </ul>
 */
final class Navigation {
    private Navigation() {
    }

    static List<Location> definition(Outline o, Doc d, int line, int column) {
        Optional<Word> w = o.wordAt(line, column);
        if (w.isEmpty()) {
            return List.of();
        }
        Optional<Outline.Reference> r = o.reference(w.get());
        if (r.isEmpty()) {
            return List.of();
        }
        long n = r.get().number();
        if (r.get().target() == Outline.Target.SEQUENCE) {
            return o.sequence(n).map(s -> List.of(new Location(d.uri(), range(s)))).orElse(List.of());
        }
        Optional<Word> here = o.program(n);
        if (here.isPresent()) {
            return List.of(new Location(d.uri(), range(here.get())));
        }
        Optional<Path> file = d.folder().flatMap(f -> Library.fileFor(f, n));
        return file.map(f -> List.of(new Location(f.toUri().toString(), new Range(new Position(0, 0), new Position(0, 0)))))
                .orElse(List.of());
    }

    static List<Location> references(Outline o, Doc d, int line, int column, boolean declaration) {
        Optional<Word> w = o.wordAt(line, column);
        if (w.isEmpty()) {
            return List.of();
        }
        Outline.Target target;
        long n;
        Optional<Outline.Reference> r = o.reference(w.get());
        if (r.isPresent()) {
            target = r.get().target();
            n = r.get().number();
        } else if (w.get().letter() == Letter.N && Outline.digits(w.get()) >= 0) {
            target = Outline.Target.SEQUENCE;
            n = Outline.digits(w.get());
        } else if (w.get().letter() == Letter.O && Outline.digits(w.get()) >= 0) {
            target = Outline.Target.PROGRAM;
            n = Outline.digits(w.get());
        } else {
            return List.of();
        }
        List<Location> out = new ArrayList<>();
        if (declaration) {
            (target == Outline.Target.SEQUENCE ? o.sequence(n) : o.program(n))
                    .ifPresent(s -> out.add(new Location(d.uri(), range(s))));
        }
        for (Outline.Reference ref : o.references()) {
            if (ref.target() == target && ref.number() == n) {
                out.add(new Location(d.uri(), range(ref.word())));
            }
        }
        return out;
    }

    /** Programs, their operations by tool change, and their canned cycles. */
    static List<DocumentSymbol> symbols(Outline o, Findings.Lines lines, gcnc.tables.ErrorMessages.Lang lang) {
        List<DocumentSymbol> top = new ArrayList<>();
        DocumentSymbol program = null;
        DocumentSymbol operation = null;
        List<RawBlock> blocks = o.blocks();
        for (RawBlock b : blocks) {
            if (b.words().isEmpty()) {
                continue;
            }
            Range whole = lines.wholeLine(b.line());
            Word first = b.words().get(0);
            if (first.letter() == Letter.O && Outline.digits(first) >= 0) {
                close(operation, lines, b.line() - 1);
                close(program, lines, b.line() - 1);
                operation = null;
                program = symbol("O" + first.number(), comment(lines.line(b.line())), SymbolKind.Module, whole, range(first));
                top.add(program);
                continue;
            }
            for (Word w : b.words()) {
                OptionalLong tool = Outline.tool(w);
                if (tool.isPresent() && tool.getAsLong() > 0) {
                    close(operation, lines, b.line() - 1);
                    operation = symbol("T" + w.number(), comment(lines.line(b.line())), SymbolKind.Function, whole, range(w));
                    (program != null ? program.getChildren() : top).add(operation);
                }
                Optional<GFunction> g = o.g(w);
                if (g.isPresent() && g.get().role().name().endsWith("CYCLE")) {
                    String text = lang == gcnc.tables.ErrorMessages.Lang.ES ? g.get().spanish() : g.get().english();
                    DocumentSymbol cycle = symbol(g.get().name(), text, SymbolKind.Event, whole, range(w));
                    (operation != null ? operation.getChildren() : program != null ? program.getChildren() : top).add(cycle);
                }
            }
        }
        if (!blocks.isEmpty()) {
            int last = blocks.get(blocks.size() - 1).line();
            close(operation, lines, last);
            close(program, lines, last);
        }
        return top;
    }

    private static DocumentSymbol symbol(String name, String detail, SymbolKind kind, Range line, Range selection) {
        DocumentSymbol s = new DocumentSymbol(name, kind, new Range(line.getStart(), line.getEnd()), selection, detail);
        s.setChildren(new ArrayList<>());
        return s;
    }

    /** A program or operation runs through line {@code last} (1-based: the line before the next one starts). */
    private static void close(DocumentSymbol s, Findings.Lines lines, int last) {
        if (s == null) {
            return;
        }
        Position end = lines.wholeLine(last).getEnd();
        if (end.getLine() > s.getRange().getStart().getLine()) {
            s.setRange(new Range(s.getRange().getStart(), end));
        }
    }

    /** The text of a line's first ( ) comment, or null. */
    private static String comment(String line) {
        int open = line.indexOf('(');
        int shut = open < 0 ? -1 : line.indexOf(')', open);
        return shut > open + 1 ? line.substring(open + 1, shut).strip() : null;
    }

    static Range range(Word w) {
        int line = w.span().line() - 1;
        int start = w.span().column() - 1;
        int end = w.span().hasEnd() ? w.span().endColumn() - 1 : start + 1 + w.number().length();
        return new Range(new Position(line, start), new Position(line, end));
    }
}
