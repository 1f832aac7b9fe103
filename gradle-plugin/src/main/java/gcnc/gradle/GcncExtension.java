package gcnc.gradle;

import gcnc.Session;
import java.io.File;
import java.util.ArrayList;
import java.util.List;
import org.gradle.api.Project;
import org.gradle.api.file.FileCollection;

/**
 * What a shop writes in {@code gcnc { }}: the machine profile (a name among the tables' machines,
 * or a path to a .machine file), a control that replaces the profile's (a name or a folder), a
 * folder with the shop's own copy of tables/ (else the tables built into gcnc), and the part
 * programs (by default every file under src/main/gcode), and whether errors fail the build
 * ({@code ignoreFailures}). Paths are relative to the project.
 */
public class GcncExtension {
    private final Project project;
    private String machine = Session.Options.defaults().machine();
    private String control;
    private File tables;
    private FileCollection programs;
    private boolean ignoreFailures;

    public GcncExtension(Project project) {
        this.project = project;
        this.programs = project.fileTree("src/main/gcode");
    }

    public String getMachine() {
        return machine;
    }

    public void setMachine(String machine) {
        this.machine = machine;
    }

    public String getControl() {
        return control;
    }

    public void setControl(String control) {
        this.control = control;
    }

    public File getTables() {
        return tables;
    }

    public void setTables(Object folder) {
        this.tables = folder == null ? null : project.file(folder);
    }

    public FileCollection getPrograms() {
        return programs;
    }

    public void setPrograms(FileCollection programs) {
        this.programs = programs;
    }

    /** {@code true}: errors are reported but do not fail the task (Gradle's own name for it, as on {@code Test}). */
    public boolean getIgnoreFailures() {
        return ignoreFailures;
    }

    public void setIgnoreFailures(boolean ignoreFailures) {
        this.ignoreFailures = ignoreFailures;
    }

    Project project() {
        return project;
    }

    /** The files behind the settings: the tables folder, and the machine and control when given as paths. */
    FileCollection settingFiles() {
        List<Object> files = new ArrayList<>();
        if (tables != null) {
            files.add(project.fileTree(tables));
        }
        for (String given : new String[] {machine, control}) {
            if (given != null && isPath(given)) {
                File f = project.file(given);
                files.add(f.isDirectory() ? project.fileTree(f) : f);
            }
        }
        return project.files(files.toArray());
    }

    /** A machine or control given as a path is a file of the project; a name is looked up in the tables. */
    static boolean isPath(String nameOrPath) {
        return nameOrPath.contains("/") || nameOrPath.endsWith(".machine");
    }
}
