package gcnc.parse;

import gcnc.diag.Diagnostics;
import java.io.CharArrayReader;
import java.io.IOException;

/**
 * Throwaway measurement, not a test: generates 1,000,000 typical blocks in memory and prints how
 * many blocks per second BlockReader returns; argument "lexer" measures the ANTLR-lexer path
 * alone. The command is in docs/grammar.md.
 */
public final class BlockReaderSpeed {
    private BlockReaderSpeed() {
    }

    public static void main(String[] args) throws IOException {
        int count = 1_000_000;
        boolean fastPath = args.length == 0 || !args[0].equals("lexer");
        StringBuilder sb = new StringBuilder(count * 34);
        for (int i = 1; i <= count; i++) {
            sb.append('N').append(i).append(" G01 X").append(i % 100).append(".345 Z-45.678 F0.2\n");
        }
        char[] text = sb.toString().toCharArray();
        for (int round = 1; round <= 5; round++) {
            Diagnostics d = new Diagnostics();
            BlockReader reader = new BlockReader(new CharArrayReader(text), d, fastPath);
            long t0 = System.nanoTime();
            int n = 0;
            int words = 0;
            while (true) {
                var b = reader.next();
                if (b == null) {
                    break;
                }
                n++;
                words += b.words().size();
            }
            double s = (System.nanoTime() - t0) / 1e9;
            System.out.printf("round %d: %d blocks (%d words, %d errors) in %.3f s = %.0f blocks/s%n",
                    round, n, words, d.errorCount(), s, n / s);
        }
    }
}
