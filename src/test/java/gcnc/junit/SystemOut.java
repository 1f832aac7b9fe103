package gcnc.junit;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

/**
 * What the fixtures print on standard output while a piece of a test runs (their note of the files a
 * folder's scan skipped, which a shop's build log shows): captured for the test to read, so that the
 * test run's own console carries none of it.
 */
final class SystemOut {
    private SystemOut() {
    }

    interface Body<T> {
        T run() throws Exception;
    }

    record Printed<T>(T value, String text) {
    }

    static synchronized <T> Printed<T> capture(Body<T> body) throws Exception {
        PrintStream console = System.out;
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        System.setOut(new PrintStream(bytes, true, StandardCharsets.UTF_8));
        try {
            T value = body.run();
            return new Printed<>(value, bytes.toString(StandardCharsets.UTF_8));
        } finally {
            System.setOut(console);
        }
    }
}
