package gcnc.gradle;

import gcnc.Session;
import gcnc.StockText;
import gcnc.sim.SimOptions;
import java.io.File;
import org.gradle.api.GradleException;
import org.gradle.api.tasks.OutputDirectory;

/**
 * What the two tasks that simulate and write files per program share (gcncCompile, gcncSimulate):
 * one output folder, emptied before all programs are judged afresh, and the simulation each program
 * starts from: the blank of {@code gcnc { stock }} read for that program as {@code --stock} is on the
 * command line ({@link StockText}: a value without a unit in the program's own units), else the
 * session's (the program's stock header, else the profile's blank).
 */
public abstract class WritingTask extends GcncTask {
    @OutputDirectory
    public File getOutputDir() {
        return outputFolder();
    }

    /** Where this task writes its programs' files. */
    protected abstract File outputFolder();

    @Override
    protected void clearOutputs() {
        getProject().delete(getOutputDir());
        getOutputDir().mkdirs();
    }

    /**
     * How {@code program}'s simulation starts; a {@code stock} that is not a blank, or one the machine
     * cannot hold, fails the task with the command line's message. What a value without a unit was read
     * as is logged at --info, once a program.
     */
    protected SimOptions simulation(Session session, Program program) {
        String given = getStock();
        if (given == null) {
            return session.simulation();
        }
        StockText.Read read;
        try {
            read = StockText.read("gcnc { stock }", given, session.profile(), program.file().toPath());
        } catch (StockText.Bad e) {
            throw new GradleException(getName() + ": " + e.getMessage());
        }
        if (read.unitless()) {
            getLogger().info("{}: {}: stock {} read in {}", getName(), program.shown(), given, read.declared()
                    .map(d -> (read.inch() ? "inches" : "millimetres") + " (" + d.word() + " at line " + d.line() + ")")
                    .orElse("millimetres (the program says neither G20 nor G21 before its first move)"));
        }
        return read.options();
    }
}
