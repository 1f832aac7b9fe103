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
 * programs (by default every file under src/main/gcode), the blank gcncCompile and gcncSimulate
 * simulate ({@code stock}, as {@code --stock} on the command line), and whether errors fail the
 * build ({@code ignoreFailures}). Paths are relative to the project.
 */
public class GcncExtension {
    private final Project project;
    private String machine = Session.Options.defaults().machine();
    private String control;
    private File tables;
    private String stock;
    private FileCollection programs;
    private boolean ignoreFailures;
    private List<String> extensions = gcnc.ProgramFiles.EXTENSIONS;
    /**
     * The findings already printed in this build (as GCC-style lines): gcncCheck, gcncCompile and
     * gcncSimulate each judge every program, and a warning printed by the first is not printed again
     * by the others (each task's JSON, SARIF and HTML reports still list all of its own). The
     * extension lives as long as the project object, one build.
     */
    final java.util.Set<String> printed = java.util.concurrent.ConcurrentHashMap.newKeySet();

    public GcncExtension(Project project) {
        this.project = project;
        // by default the programs under src/main/gcode whose names end in one of the extensions (any
        // case), as the command line finds them in a folder: the extensions are read when Gradle
        // walks the tree, so `extensions = [...]` later in the build script holds
        this.programs = project.fileTree("src/main/gcode", tree -> tree.include(
                f -> f.isDirectory() || gcnc.ProgramFiles.isProgram(f.getName(), extensions)));
    }

    /**
     * The extensions of the part programs (default: nc, ngc, tap, gcode: {@code gcnc.ProgramFiles}),
     * shared with the command line and with the shop's tests (the JUnit fixtures' everyProgramIn
     * read it from the system property gcnc.extensions, which the plugin sets on every test task).
     */
    public List<String> getExtensions() {
        return extensions;
    }

    public void setExtensions(List<String> extensions) {
        this.extensions = gcnc.ProgramFiles.normal(extensions);
    }

    /** The files under src/main/gcode that are not programs by their extension (for the tasks' note). */
    List<File> skipped() {
        File folder = project.file("src/main/gcode");
        if (ownPrograms || !folder.isDirectory()) {
            return List.of();
        }
        List<File> out = new ArrayList<>();
        project.fileTree(folder).forEach(f -> {
            if (!f.getName().startsWith(".") && !gcnc.ProgramFiles.isProgram(f.getName(), extensions)) {
                out.add(f);
            }
        });
        return out;
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

    /**
     * The blank, as {@code gcnc compile --stock} takes it ({@code gcnc.StockText}): {@code
     * DIA,LENGTH[,STICKOUT[,BORE]]}, each value with its unit ({@code '1.75in,4in,2in'}) or in the
     * program's units (G20 or G21 in its head, else mm), or {@code 'none'}; null (the default): the
     * program's stock header, else the profile's blank.
     */
    public String getStock() {
        return stock;
    }

    public void setStock(String stock) {
        this.stock = stock;
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
        this.ownPrograms = true;
    }

    /** Whether the build script named its programs (then the plugin does not judge what src/main/gcode holds). */
    private boolean ownPrograms;

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
