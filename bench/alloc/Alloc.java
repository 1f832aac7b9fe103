import gcnc.Compiler;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.BufferedReader;
import java.io.FileReader;
import java.io.Reader;
import java.util.Optional;

/** The bytes the checking thread allocates to check a program on the generic machine (bench/alloc.sh). */
public class Alloc {
    public static void main(String[] args) throws Exception {
        Tables tables = Tables.builtIn();
        var profile = ProfileLoader.load("generic", TableSource.builtIn(), tables);
        var threads = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        for (int run = 1; run <= 2; run++) {
            long before = threads.getThreadAllocatedBytes(id);
            try (Reader in = new BufferedReader(new FileReader(args[0]))) {
                Compiler.check(in, new Compiler.Settings(tables, profile, gcnc.galil.Dialect.Kind.GALIL, Optional.empty()));
            }
            System.out.printf("run %d: %d MB allocated%n", run, (threads.getThreadAllocatedBytes(id) - before) / 1_000_000);
        }
    }
}
