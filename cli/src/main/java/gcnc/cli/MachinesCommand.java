package gcnc.cli;

import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.PrintWriter;
import java.net.URI;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.FileSystem;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Parameters;

/** {@code gcnc machines}: the machine profiles gcnc ships (or --tables holds), one shown, one file validated. */
@Command(name = "machines", mixinStandardHelpOptions = true,
        description = "List the machine profiles (tables/machines/, or --tables DIR/machines/): name, control,"
                + " Galil model and what the lathe is.",
        subcommands = {MachinesCommand.Show.class, MachinesCommand.Validate.class},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:listed; every profile loads", "2:a profile is broken (reported where), or a broken table"})
final class MachinesCommand extends StreamsCommand {
    @Mixin
    CommonOptions common;

    @Override
    Integer call(PrintWriter out, PrintWriter err) {
        Tables tables;
        List<String> names;
        try {
            tables = common.loadTables();
            names = names(common.tables);
        } catch (TableException e) {
            return Reporter.tableFault(err, e, common.language());
        } catch (IOException e) {
            err.println(new Phrases(common.language()).get("machines.cannot_list", SourceFiles.reason(e, common.language())));
            return ExitCode.USAGE;
        }
        int status = ExitCode.CLEAN;
        Phrases phrases = new Phrases(common.language());
        for (String name : names) {
            try {
                MachineProfile p = ProfileLoader.load(name, common.source(), tables, null);
                String text = common.source().read("machines/" + name + ".machine");
                out.println(phrases.get("machines.row", String.format("%-14s", name),
                        String.format("%-12s", p.control().name()), String.format("%-9s", p.galilModel().name()), summary(text)));
            } catch (TableException e) {
                status = Reporter.tableFault(err, e, common.language());
            }
        }
        out.flush();
        return status;
    }

    /** The profile's own description: the first sentence of its opening comment, after "name --". */
    static String summary(String text) {
        StringBuilder b = new StringBuilder();
        for (String line : text.split("\n")) {
            if (!line.startsWith("#")) {
                break;
            }
            b.append(line.substring(1).strip()).append(' ');
        }
        String s = b.toString().strip();
        int dash = s.indexOf("--");
        if (dash >= 0) {
            s = s.substring(dash + 2).strip();
        }
        int end = s.indexOf(". ");
        return end >= 0 ? s.substring(0, end + 1) : s;
    }

    /** The names of the profiles in DIR/machines, or in the jar's (or the build's) tables/machines. */
    static List<String> names(Path dir) throws IOException {
        if (dir != null) {
            return names(list(dir.resolve("machines")));
        }
        URL url = TableSource.class.getResource("/tables/machines");
        if (url == null) {
            throw new IOException("no tables/machines in gcnc's class path");
        }
        try {
            URI uri = url.toURI();
            if (uri.getScheme().equals("jar")) {
                try (FileSystem jar = FileSystems.newFileSystem(uri, Map.of())) {
                    return names(list(jar.getPath("/tables/machines")));
                } catch (java.nio.file.FileSystemAlreadyExistsException open) {
                    // Someone else in this JVM has the jar open: read through theirs, and leave it open.
                    return names(list(FileSystems.getFileSystem(uri).getPath("/tables/machines")));
                }
            }
            return names(list(Path.of(uri)));
        } catch (URISyntaxException e) {
            throw new IOException(e.getMessage(), e);
        }
    }

    private static List<Path> list(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.toList();
        }
    }

    private static List<String> names(List<Path> files) {
        List<String> names = new ArrayList<>();
        for (Path f : files) {
            String n = f.getFileName().toString();
            if (n.endsWith(".machine")) {
                names.add(n.substring(0, n.length() - ".machine".length()));
            }
        }
        names.sort(null);
        return names;
    }

    /** {@code gcnc machines show NAME}: the profile file as it is, after checking that it loads. */
    @Command(name = "show", mixinStandardHelpOptions = true,
            description = "Print a machine profile (a name or a .machine file) as written, once it has loaded.")
    static final class Show extends StreamsCommand {
        @Mixin
        CommonOptions common;

        @Parameters(paramLabel = "NAME|PATH", description = "A profile name (gcnc machines lists them) or a .machine file.")
        String name;

        @Override
        Integer call(PrintWriter out, PrintWriter err) {
            try {
                Tables tables = common.loadTables();
                ProfileLoader.load(name, common.source(), tables, null);
                boolean file = ProfileLoader.isPath(name);
                String text = file ? Files.readString(Path.of(name)) : common.source().read("machines/" + name + ".machine");
                out.print(text);
                out.flush();
                return ExitCode.CLEAN;
            } catch (TableException e) {
                return Reporter.tableFault(spec.commandLine().getErr(), e, common.language());
            } catch (IOException e) {
                spec.commandLine().getErr().println("gcnc: " + Printable.escape(name) + ": " + SourceFiles.reason(e, common.language()));
                return ExitCode.USAGE;
            }
        }
    }

    /** {@code gcnc machines validate FILE}: the load-time validation of a profile, for a shop's own file. */
    @Command(name = "validate", mixinStandardHelpOptions = true,
            description = "Load machine profiles as a run would and report every fault found, with its line.",
            exitCodeListHeading = "%nExit status:%n",
            exitCodeList = {"0:every profile is valid", "2:a profile has a fault (printed with its line and column)"})
    static final class Validate extends StreamsCommand {
        @Mixin
        CommonOptions common;

        @Mixin
        ReportOptions report;

        @Parameters(arity = "1..*", paramLabel = "FILE", description = ".machine files to validate (or profile names).")
        List<String> files;

        @Override
        Integer call(PrintWriter out, PrintWriter err) {
            Reporter reporter = new Reporter(report.format, report.quiet, out, err, common.language());
            int status = validate(reporter);
            reporter.finish();
            out.flush();
            return status;
        }

        private int validate(Reporter reporter) {
            Tables tables;
            try {
                tables = common.loadTables();
            } catch (TableException e) {
                return reporter.tableFault(e);
            }
            reporter.use(tables, common.source());
            int status = ExitCode.CLEAN;
            for (String f : files) {
                // A file in the current folder named without ".machine" would be taken for a profile name.
                String path = Files.isRegularFile(Path.of(f)) && !ProfileLoader.isPath(f) ? "./" + f : f;
                try {
                    MachineProfile p = ProfileLoader.load(path, common.source(), tables, common.control);
                    reporter.say(reporter.phrases().get("machines.valid", f, p.name(), p.control().name()));
                } catch (TableException e) {
                    status = reporter.tableFault(e);
                }
            }
            return status;
        }
    }
}
