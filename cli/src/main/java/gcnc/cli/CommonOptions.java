package gcnc.cli;

import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.nio.file.Path;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** Options every command shares: where tables come from, which machine, which language. */
final class CommonOptions {
    @Option(names = "--tables", paramLabel = "DIR",
            description = "Read the tables from DIR (an edited copy of tables/) instead of the built-in ones.")
    Path tables;

    @Option(names = "--machine", paramLabel = "NAME|PATH", defaultValue = ProfileLoader.DEFAULT,
            description = "Machine profile: a name under tables/machines/ or a .machine file (default: ${DEFAULT-VALUE}).")
    String machine;

    @Option(names = "--control", paramLabel = "NAME|PATH",
            description = "Control whose G and M codes and rules apply: a name under tables/controls/ or a folder"
                    + " (default: the one the machine profile names).")
    String control;

    @Option(names = "--offsets", paramLabel = "FILE",
            description = "The tools' wear offsets: a file of wear.N = X, Z lines (default: the profile's offsets.file, if any).")
    Path offsets;

    @Mixin
    LanguageOption lang;

    /** The command these options belong to: its root holds a {@code --lang} given before the command. */
    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    /** What every command needs once its options are read: the library session (tables, machine), a reporter. */
    record Setup(gcnc.Session session, Reporter reporter) {
        Tables tables() {
            return session.tables();
        }

        MachineProfile profile() {
            return session.profile();
        }
    }

    /**
     * Loads the tables and the machine through the library's {@link gcnc.Session}, and gives the
     * tables' messages to {@code reporter}; a broken one is reported by the caller with
     * {@link Reporter#tableFault}.
     */
    Setup load(Reporter reporter) throws TableException {
        return load(reporter, false);
    }

    /** {@link #load(Reporter)}; with {@code newOffsets} an offsets file that does not exist yet reads as empty (the test cut makes it). */
    Setup load(Reporter reporter, boolean newOffsets) throws TableException {
        gcnc.Session.Options o = gcnc.Session.Options.defaults().withMachine(machine);
        if (tables != null) {
            o = o.withTables(tables);
        }
        if (control != null) {
            o = o.withControl(control);
        }
        if (offsets != null) {
            o = o.withOffsets(offsets);
        }
        if (newOffsets) {
            o = o.withNewOffsets();
        }
        gcnc.Session s = gcnc.Session.open(o);
        reporter.use(s.tables(), source());
        return new Setup(s, reporter);
    }

    TableSource source() {
        return tables == null ? TableSource.builtIn() : TableSource.directory(tables);
    }

    Tables loadTables() throws TableException {
        return Tables.load(source());
    }

    MachineProfile loadProfile(Tables t) throws TableException {
        return ProfileLoader.load(machine, source(), t, control, java.util.Optional.ofNullable(offsets), false);
    }

    /** This command's {@code --lang}, else one before the command ({@code gcnc --lang es check}), else the locale's. */
    ErrorMessages.Lang language() {
        return lang.language(mixee);
    }
}
