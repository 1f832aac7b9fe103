package gcnc.gradle;

import gcnc.Compiler;
import gcnc.Session;
import java.io.IOException;
import java.io.Reader;

/** {@code gcncCheck}: parse and every check of every program, as {@code gcnc check} does; no output but the reports. */
public class CheckTask extends GcncTask {
    @Override
    protected void process(Session session, Program program, TaskFindings findings) throws IOException {
        try (Reader in = program.open()) {
            Compiler.Result r = session.check(in);
            findings.report(program.shown(), r.diagnostics());
        }
    }
}
