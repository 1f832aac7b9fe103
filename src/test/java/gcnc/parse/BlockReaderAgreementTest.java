package gcnc.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.diag.Diagnostics;
import gcnc.parse.gen.GCodeBaseVisitor;
import gcnc.parse.gen.GCodeLexer;
import gcnc.parse.gen.GCodeParser;
import java.io.IOException;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.tree.TerminalNode;
import org.junit.jupiter.api.Test;

/**
 * BlockReader against the grammar: the parser rule {@code program} over the whole text must see
 * the same blocks (same line, words, columns) and reject exactly the programs BlockReader
 * reports; and BlockReader's fast path must give exactly what the ANTLR lexer path gives.
 */
class BlockReaderAgreementTest {

    /** Blocks as "line: word@column ..." per the grammar, plus whether the parser saw an error. */
    private static List<String> grammarBlocks(String src, boolean[] rejected) {
        GCodeLexer lexer = new GCodeLexer(CharStreams.fromString(src));
        GCodeParser parser = new GCodeParser(new CommonTokenStream(lexer));
        BaseErrorListener flag = new BaseErrorListener() {
            @Override
            public void syntaxError(Recognizer<?, ?> r, Object o, int l, int c, String m, RecognitionException e) {
                rejected[0] = true;
            }
        };
        lexer.removeErrorListeners();
        parser.removeErrorListeners();
        lexer.addErrorListener(flag);
        parser.addErrorListener(flag);
        List<String> out = new ArrayList<>();
        new GCodeBaseVisitor<Void>() {
            @Override
            public Void visitBlock(GCodeParser.BlockContext ctx) {
                StringBuilder sb = new StringBuilder().append(ctx.getStart().getLine()).append(':');
                StringBuilder words = new StringBuilder();
                for (int i = 0; i < ctx.getChildCount(); i++) {
                    Token t = ctx.getChild(i) instanceof TerminalNode n ? n.getSymbol()
                            : ((GCodeParser.WordContext) ctx.getChild(i)).getStart();
                    String text = t.getText();
                    if (t.getType() == GCodeLexer.BLOCK_DELETE) {
                        sb.append(" /").append(text.length() > 1 ? text.substring(1) : "1");
                        continue;
                    }
                    text = text.replace(" ", "").replace("\t", ""); // 'X 5.' is X5.
                    String comma = text.startsWith(",") ? "," : "";
                    text = text.substring(comma.length());
                    char letter = text.charAt(0) == ':' ? 'O' : Character.toUpperCase(text.charAt(0));
                    words.append(' ').append(comma).append(letter).append(text.substring(1))
                            .append('@').append(t.getCharPositionInLine() + 1);
                }
                out.add(sb.append(words).toString());
                return null;
            }
        }.visit(parser.program());
        return out;
    }

    private static List<String> readerBlocks(Parsed p) {
        List<String> out = new ArrayList<>();
        p.blocks().forEach(b -> {
            StringBuilder sb = new StringBuilder().append(b.line()).append(':');
            if (b.blockDelete() > 0) {
                sb.append(" /").append(b.blockDelete());
            }
            b.words().forEach(w -> sb.append(' ').append(w).append('@').append(w.span().column()));
            out.add(sb.toString());
        });
        return out;
    }

    @Test
    void validProgramsGiveTheSameBlocksAsTheGrammar() {
        for (long seed = 1; seed <= 200; seed++) {
            String src = new Soup(seed).validProgram(1 + (int) (seed % 30));
            boolean[] rejected = {false};
            List<String> expected = grammarBlocks(src, rejected);
            Parsed p = Parsed.of(src);
            String where = "seed " + seed + " " + BlockReaderFuzzTest.escape(src);
            assertEquals(false, rejected[0], "grammar rejects " + where);
            assertEquals(List.of(), p.errors(), where);
            assertEquals(expected, readerBlocks(p), where);
        }
    }

    @Test
    void theGrammarRejectsExactlyWhatTheReaderReports() {
        for (long seed = 1; seed <= 400; seed++) {
            Soup soup = new Soup(seed);
            String src = (seed % 2 == 0 ? soup.tokenSoup(1 + (int) (seed % 40)) : soup.mutatedProgram(5))
                    .replace("\uFEFF", "");
            boolean[] rejected = {false};
            grammarBlocks(src, rejected);
            Parsed p = Parsed.of(src);
            // the grammar has no warnings (E600: a space in a number): it rejects what is an error
            assertEquals(rejected[0], p.diagnostics().stream().anyMatch(d -> d.severity() == gcnc.diag.Severity.ERROR),
                    "seed " + seed + " " + BlockReaderFuzzTest.escape(src) + " " + p.errors());
        }
    }

    /** The slip hints (120, 121) only name lines the grammar rejects anyway, the same on both paths. */
    @Test
    void slipHintsAreOnlyGivenForLinesTheGrammarRejects() throws IOException {
        String src = "G01 Z-3O. F.2\nG00 Z,15\nG00 Z-30,5 (note)\nG0OX1.\nN10 G00 X1O5\nG00 X1. Z2.\n";
        boolean[] rejected = {false};
        grammarBlocks(src, rejected);
        assertEquals(true, rejected[0]);
        Parsed fast = Parsed.of(src);
        assertEquals(List.of("1:5 E120 [Z-3O., Z-30.]", "2:5 E121 [Z,15, Z.15]", "3:5 E121 [Z-30,5, Z-30.5]",
                "4:1 E120 [G0O, G00]"), fast.errors());
        Diagnostics d = new Diagnostics();
        BlockReader slow = new BlockReader(new StringReader(src), d, false);
        List<gcnc.ir.RawBlock> blocks = new ArrayList<>();
        for (var b = slow.next(); b != null; b = slow.next()) {
            blocks.add(b);
        }
        assertEquals(blocks, fast.blocks());
        assertEquals(d.sorted(), fast.diagnostics());
        // X1O5 lexes (X1 and a program number O5): the grammar's to accept, the checker's to name
        boolean[] fine = {false};
        grammarBlocks("N10 G00 X1O5\n", fine);
        assertEquals(false, fine[0]);
    }

    @Test
    void fastPathAndLexerPathAgree() throws IOException {
        for (long seed = 1; seed <= 400; seed++) {
            Soup soup = new Soup(seed);
            String src = seed % 3 == 0 ? soup.tokenSoup(60) : soup.mutatedProgram(20);
            Parsed fast = Parsed.of(src);
            Diagnostics d = new Diagnostics();
            BlockReader slow = new BlockReader(new StringReader(src), d, false);
            List<gcnc.ir.RawBlock> blocks = new ArrayList<>();
            for (var b = slow.next(); b != null; b = slow.next()) {
                blocks.add(b);
            }
            String where = "seed " + seed + " " + BlockReaderFuzzTest.escape(src);
            assertEquals(blocks, fast.blocks(), where);
            assertEquals(d.sorted(), fast.diagnostics(), where);
        }
    }
}
