package gcnc.gradle;

import org.gradle.api.Plugin;
import org.gradle.api.Project;
import org.gradle.language.base.plugins.LifecycleBasePlugin;

/**
 * The plugin {@code gcnc}: the extension {@code gcnc { machine; control; tables; programs }} and
 * three tasks over it, {@code gcncCheck} (part of {@code check}), {@code gcncCompile} (DMC and
 * source maps under build/gcnc/) and {@code gcncSimulate} (drawings and setup sheets under
 * build/reports/gcnc/). Each writes a JSON and a SARIF report of its findings.
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
