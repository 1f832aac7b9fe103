import gcnc.Compiler;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.BufferedReader;
import java.io.FileReader;
import java.io.Reader;
import java.util.Optional;

/**
 * The checking thread's CPU milliseconds for each of N checks of a program in one JVM, on the
 * generic machine (bench/warm.sh): the later runs show the checker warm, without the JIT
 * compilation that is half of a cold run.
 */
public class Warm {
    public static void main(String[] args) throws Exception {
        Tables tables = Tables.builtIn();
        var profile = ProfileLoader.load("generic", TableSource.builtIn(), tables);
        var threads = java.lang.management.ManagementFactory.getThreadMXBean();
        int runs = Integer.parseInt(args[1]);
        StringBuilder line = new StringBuilder();
        for (int run = 1; run <= runs; run++) {
            long before = threads.getCurrentThreadCpuTime();
            try (Reader in = new BufferedReader(new FileReader(args[0]))) {
                Compiler.check(in, new Compiler.Settings(tables, profile, gcnc.galil.Dialect.Kind.GALIL, Optional.empty()));
            }
            line.append(run == 1 ? "" : " ").append((threads.getCurrentThreadCpuTime() - before) / 1_000_000);
        }
        System.out.println(line + " ms");
    }
}
