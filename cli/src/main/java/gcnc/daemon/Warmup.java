package gcnc.daemon;

import gcnc.cli.Main;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;

/**
 * Before the server takes requests, it checks and compiles a 2,000-block turning program a dozen
 * times (roughing passes with arcs, as bench/gen_program.py writes): the JIT compiles the hot code
 * once, at start, instead of in the first runs a user waits for.
 */
final class Warmup {
    /**
     * Rounds of check (and of compile and simulate every other round): after a dozen a check's own
     * thread no longer gets faster and the JIT's threads have little left to compile (measured with a
     * loop of Main.execute, issue 23). At most {@link #LONGEST_NS} on a slow machine.
     */
    private static final int ROUNDS = 12;
    private static final long LONGEST_NS = 30_000_000_000L;

    private Warmup() {
    }

    static void run() {
        Path dir = null;
        try {
            dir = Files.createTempDirectory("gcnc-daemon-warmup");
            Path program = dir.resolve("warmup.nc");
            Files.writeString(program, program(2000));
            String p = program.toString();
            String dmc = dir.resolve("warmup.dmc").toString();
            long until = System.nanoTime() + LONGEST_NS;
            for (int i = 0; i < ROUNDS && System.nanoTime() < until; i++) {
                quietly("check", p);
                if (i % 2 == 0) {
                    quietly("compile", p, "-o", dmc);
                    quietly("simulate", dmc);
                }
            }
        } catch (IOException | RuntimeException e) {
            // a warm-up that fails leaves the server as fast as a cold JVM, no less correct
        } finally {
            if (dir != null) {
                for (String f : new String[] {"warmup.nc", "warmup.dmc", "warmup.dmc.map"}) {
                    try {
                        Files.deleteIfExists(dir.resolve(f));
                    } catch (IOException e) {
                        // a file left in the temporary folder
                    }
                }
                try {
                    Files.deleteIfExists(dir);
                } catch (IOException e) {
                    // idem
                }
            }
        }
    }

    private static void quietly(String... args) {
        OutputStream none = OutputStream.nullOutputStream();
        Main.execute(args, new Main.Invocation(new ByteArrayInputStream(new byte[0]), none, none,
                Map.of("LANG", "C.UTF-8"), false, p -> false));
    }

    /** Roughing passes with arcs on the generic machine, as bench/gen_program.py writes them. */
    static String program(int blocks) {
        StringBuilder s = new StringBuilder("O2000\n");
        int n = 10;
        String[] header = {"G21 G90 G98", "G50 S2500", "M11", "T0101", "S1200 M03", "G00 X52. Z2."};
        for (String b : header) {
            s.append('N').append(n++).append(' ').append(b).append('\n');
        }
        double d = 50;
        for (int written = 0; written < blocks - 10; written += 5) {
            s.append(String.format(Locale.ROOT, "N%d G00 X%.3f Z2.%nN%d G01 Z-40.5 F120.%nN%d G02 X%.3f Z-41.5 R1.%n"
                    + "N%d G01 X%.3f%nN%d G00 Z2.%n", n, d, n + 1, n + 2, d + 2, n + 3, d + 4, n + 4));
            n += 5;
            d = d > 21 ? d - 0.25 : 50;
        }
        for (String b : new String[] {"G00 X60. Z5.", "M05", "M30"}) {
            s.append('N').append(n++).append(' ').append(b).append('\n');
        }
        return s.toString();
    }
}
