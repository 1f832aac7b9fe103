package gcnc.gradle;

import gcnc.Session;
import java.io.IOException;
import java.io.Reader;
import java.util.List;
import org.gradle.api.tasks.CacheableTask;

/** {@code gcncCheck}: parse and every check of every program, as {@code gcnc check} does; no output but the reports. */
@CacheableTask
public class CheckTask extends GcncTask {
    @Override
    protected Outcome process(Session session, Program program) throws IOException {
        try (Reader in = program.open()) {
            return outcome(session.check(in), List.of());
        }
    }
}
