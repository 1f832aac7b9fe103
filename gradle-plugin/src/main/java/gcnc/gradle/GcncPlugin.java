package gcnc.gradle;

import org.gradle.api.Plugin;
import java.util.concurrent.Callable;
import org.gradle.api.Project;
import org.gradle.api.Task;
import org.gradle.api.tasks.PathSensitivity;
import org.gradle.api.tasks.testing.Test;
import org.gradle.language.base.plugins.LifecycleBasePlugin;

/**
 * The plugin {@code gcnc}: the extension {@code gcnc { machine; control; tables; programs }} and
 * three tasks over it, {@code gcncCheck} (part of {@code check}), {@code gcncCompile} (DMC and
 * source maps under build/gcnc/) and {@code gcncSimulate} (drawings and setup sheets under
 * build/reports/gcnc/). Each writes a JSON and a SARIF report of its findings. The shop's own test
 * tasks get the programs and the settings' files as inputs, so an edited program runs its tests again.
 */
public class GcncPlugin implements Plugin<Project> {
    static final String GROUP = "gcnc";

    @Override
    public void apply(Project project) {
        project.getPluginManager().apply(LifecycleBasePlugin.class);
        GcncExtension settings = project.getExtensions().create("gcnc", GcncExtension.class, project);
        CheckTask check = task(project, "gcncCheck", CheckTask.class, settings,
                "Checks every part program: all errors, with file, line and column; no output.");
        task(project, "gcncCompile", CompileTask.class, settings,
                "Checks, compiles and simulates every part program: Galil programs and source maps under build/gcnc/.");
        task(project, "gcncSimulate", SimulateTask.class, settings,
                "Simulates every part program: toolpath drawing and setup sheet per program under build/reports/gcnc/.");
        project.getTasks().getByName(LifecycleBasePlugin.CHECK_TASK_NAME).dependsOn(check);
        // A shop's own tests (gcnc's JUnit fixtures) read the programs, the profile and the tables at
        // run time: Gradle only re-runs a test task when its declared inputs change, so without this an
        // edited program that breaks an assertion would leave `gradle check` green and UP-TO-DATE.
        // `all` also reaches test tasks made later (the JUnit Platform plugin makes junitPlatformTest
        // after the build script is evaluated).
        project.getTasks().all(task -> {
            if (isTestTask(task)) {
                seeTheShopsInputs(task, settings);
            }
        });
    }

    /** Gradle's {@code Test} tasks, and on Gradle 4.4 the JUnit Platform plugin's {@code junitPlatformTest} (a JavaExec). */
    static boolean isTestTask(Task task) {
        return task instanceof Test || JUNIT_PLATFORM_TEST.equals(task.getName());
    }

    static final String JUNIT_PLATFORM_TEST = "junitPlatformTest";

    /** Declares the part programs and the files behind the settings as inputs of {@code task}, resolved when Gradle asks. */
    static void seeTheShopsInputs(Task task, GcncExtension settings) {
        task.getInputs().files((Callable<Object>) () -> settings.getPrograms())
                .withPropertyName("gcncPrograms").withPathSensitivity(PathSensitivity.RELATIVE);
        task.getInputs().files((Callable<Object>) settings::settingFiles)
                .withPropertyName("gcncSettingFiles").withPathSensitivity(PathSensitivity.RELATIVE);
        task.getInputs().property("gcncMachine", (Callable<Object>) settings::getMachine);
        task.getInputs().property("gcncControl", (Callable<Object>) () -> String.valueOf(settings.getControl()));
        task.getInputs().property("gcncExtensions", (Callable<Object>) () -> String.join(",", settings.getExtensions()));
        if (task instanceof org.gradle.process.JavaForkOptions) {
            // the fixtures' everyProgramIn takes the build's list of extensions (gcnc.ProgramFiles.configured),
            // set when the task runs (after the build script); a class, not a lambda: Gradle cannot tell
            // a lambda's implementation from one build to the next, and the task would never be UP-TO-DATE
            task.doFirst(new PassExtensions(settings));
        }
    }

    /** Hands the build's list of program extensions to a test JVM as the system property gcnc.extensions. */
    static final class PassExtensions implements org.gradle.api.Action<Task> {
        private final GcncExtension settings;

        PassExtensions(GcncExtension settings) {
            this.settings = settings;
        }

        @Override
        public void execute(Task t) {
            ((org.gradle.process.JavaForkOptions) t).systemProperty(gcnc.ProgramFiles.PROPERTY,
                    String.join(",", settings.getExtensions()));
        }
    }

    private static <T extends GcncTask> T task(Project project, String name, Class<T> type, GcncExtension settings,
                                               String description) {
        T t = project.getTasks().create(name, type);
        t.setSettings(settings);
        t.setGroup(GROUP);
        t.setDescription(description);
        return t;
    }
}
