package gcnc;

import java.io.PrintStream;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.support.descriptor.ClassSource;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * The test run's progress, a line per test class as it finishes:
 * {@code gcnc.check.CycleTest: 42 passed, 0 failed (1.3 s)}, and what was skipped with the reason
 * ({@code 1 skipped: needs ../shared/corpus ...}). The JUnit Platform launcher finds it through
 * META-INF/services/org.junit.platform.launcher.TestExecutionListener, in both lanes of
 * {@code gradle junitPlatformTest}; the summary box at the end stays the console launcher's.
 */
public final class ClassProgress implements TestExecutionListener {
    /** The console as the run began: a test that redirects System.out for a while does not take these lines. */
    private final PrintStream out = System.out;
    private final Map<String, Count> counts = new HashMap<>();
    private TestPlan plan;

    /** One class's tests so far. */
    private static final class Count {
        final long began = System.nanoTime();
        int passed;
        int failed;
        int skipped;
        final Set<String> reasons = new LinkedHashSet<>();
    }

    @Override
    public void testPlanExecutionStarted(TestPlan testPlan) {
        plan = testPlan;
    }

    @Override
    public void executionStarted(TestIdentifier id) {
        if (isClass(id)) {
            counts.put(id.getUniqueId(), new Count());
        }
    }

    @Override
    public void executionSkipped(TestIdentifier id, String reason) {
        if (isClass(id)) {
            out.println(name(id) + ": skipped: " + reason);
            out.flush();
            return;
        }
        countSkipped(id, reason);
    }

    @Override
    public void executionFinished(TestIdentifier id, TestExecutionResult result) {
        if (isClass(id)) {
            finished(id, result);
            return;
        }
        if (result.getStatus() == TestExecutionResult.Status.ABORTED) {
            // an assumption: a test, or a test factory that made none, that cannot apply here
            countSkipped(id, result.getThrowable().map(Throwable::getMessage).orElse("aborted"));
            return;
        }
        Count c = countOf(id);
        if (c == null || !id.isTest()) {
            return;
        }
        if (result.getStatus() == TestExecutionResult.Status.SUCCESSFUL) {
            c.passed++;
        } else {
            c.failed++;
        }
    }

    private void countSkipped(TestIdentifier id, String reason) {
        Count c = countOf(id);
        if (c != null) {
            c.skipped++;
            c.reasons.add(reason.replaceFirst("^Assumption failed: ", ""));
        }
    }

    private void finished(TestIdentifier id, TestExecutionResult result) {
        Count c = counts.remove(id.getUniqueId());
        if (c == null) {
            return;
        }
        StringBuilder line = new StringBuilder(name(id)).append(": ").append(c.passed).append(" passed, ")
                .append(c.failed).append(" failed");
        if (c.skipped > 0) {
            line.append(", ").append(c.skipped).append(" skipped (").append(String.join("; ", c.reasons)).append(')');
        }
        if (result.getStatus() == TestExecutionResult.Status.FAILED) {
            // a @BeforeAll or @AfterAll that failed: the class failed though no test of it did
            line.append(", the class itself failed: ").append(result.getThrowable().map(Throwable::toString).orElse("?"));
        }
        line.append(String.format(Locale.ROOT, " (%.1f s)", (System.nanoTime() - c.began) / 1e9));
        out.println(line);
        out.flush();
    }

    /** The count of the nearest test class above {@code id}, or null. */
    private Count countOf(TestIdentifier id) {
        Optional<TestIdentifier> at = Optional.of(id);
        while (at.isPresent()) {
            Count c = counts.get(at.get().getUniqueId());
            if (c != null && isClass(at.get())) {
                return c;
            }
            at = plan == null ? Optional.empty() : plan.getParent(at.get());
        }
        return null;
    }

    private static boolean isClass(TestIdentifier id) {
        return id.getSource().filter(s -> s instanceof ClassSource).isPresent();
    }

    private static String name(TestIdentifier id) {
        return id.getSource().map(s -> ((ClassSource) s).getClassName()).orElse(id.getDisplayName());
    }
}
