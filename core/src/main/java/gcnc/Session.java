package gcnc;

import gcnc.dmc.Form;
import gcnc.machine.MachineProfile;
import gcnc.output.FormOutputs;
import gcnc.machine.ProfileLoader;
import gcnc.sim.SimOptions;
import gcnc.sim.StockSize;
import gcnc.tables.CodeTable;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * The one way in for every front end (the command line, the JUnit fixtures, later the Gradle
 * plugin and the studio): what a run is given (tables, machine, control, dialect, blank) is
 * resolved here, once, the same for all of them, so that they give the same verdict on the same
 * program. A session is immutable and can check or compile any number of programs.
 */
public final class Session {
    /**
     * What a run is given, as a user gives it.
     *
     * @param tables  a folder with an edited copy of tables/, or empty for the built-in tables
     * @param machine a profile name under tables/machines/ or a path to a .machine file
     * @param control a control name or folder that replaces the one the profile names, or empty
     * @param dialect the DMC dialect to write
     * @param stock   the blank (else the program's stock header, else the profile's blank)
     * @param offsets the offsets file with the tools' wear ({@code --offsets FILE}; else the profile's
     *                {@code offsets.file}, if any)
     * @param newOffsets the offsets file may not exist yet and is then read as empty (the test cut,
     *                {@code gcnc offsets wear}, creates it); otherwise a missing one is E455
     */
    public record Options(Optional<Path> tables, String machine, Optional<String> control, gcnc.galil.Dialect.Kind dialect,
                          Optional<StockSize> stock, Optional<Path> offsets, boolean newOffsets) {
        /** The built-in tables, the default machine, its own control, the galil dialect, no blank given. */
        public static Options defaults() {
            return new Options(Optional.empty(), ProfileLoader.DEFAULT, Optional.empty(), gcnc.galil.Dialect.Kind.GALIL, Optional.empty(),
                    Optional.empty(), false);
        }

        public Options withTables(Path folder) {
            return new Options(Optional.of(folder), machine, control, dialect, stock, offsets, newOffsets);
        }

        public Options withMachine(String nameOrPath) {
            return new Options(tables, nameOrPath, control, dialect, stock, offsets, newOffsets);
        }

        public Options withControl(String nameOrPath) {
            return new Options(tables, machine, Optional.of(nameOrPath), dialect, stock, offsets, newOffsets);
        }

        public Options withDialect(gcnc.galil.Dialect.Kind kind) {
            return new Options(tables, machine, control, kind, stock, offsets, newOffsets);
        }

        public Options withStock(StockSize blank) {
            return new Options(tables, machine, control, dialect, Optional.of(blank), offsets, newOffsets);
        }

        /** These options with the wear offsets of {@code file} ({@code --offsets FILE}). */
        public Options withOffsets(Path file) {
            return new Options(tables, machine, control, dialect, stock, Optional.of(file), false);
        }

        /** Reading an offsets file that may not exist yet as empty: the test cut creates it (else E455). */
        public Options withNewOffsets() {
            return new Options(tables, machine, control, dialect, stock, offsets, true);
        }

        TableSource source() {
            return tables.map(TableSource::directory).orElse(TableSource.builtIn());
        }
    }

    private final Options options;
    private final Tables tables;
    private final MachineProfile profile;
    /** Where programs a program calls (M98) are looked for besides the program itself. */
    private final Optional<Path> programs;

    private Session(Options options, Tables tables, MachineProfile profile, Optional<Path> programs) {
        this.options = options;
        this.tables = tables;
        this.profile = profile;
        this.programs = programs;
    }

    /** Loads the tables and the machine profile; a broken table or profile is a {@link TableException} at its file and line. */
    public static Session open(Options options) throws TableException {
        if (Shipped.covers(options)) {
            Tables t = Shipped.tables();
            return new Session(options, t, Shipped.profile(options, t), Optional.empty());
        }
        Tables t = Tables.load(options.source());
        MachineProfile p = ProfileLoader.load(options.machine(), options.source(), t, options.control().orElse(null),
                options.offsets(), options.newOffsets());
        return new Session(options, t, p, Optional.empty());
    }

    /**
     * The tables and the profiles gcnc ships, read and checked once per JVM: they are inside the
     * jar and cannot change while it runs, and a resident checker would otherwise read them again
     * for every request (about 4 ms of a 30 ms compile of 2,000 blocks). A {@code --tables}
     * folder, a profile or control given as a path, or an offsets file, is read every time: its user may be editing
     * it. Both are immutable values, so sharing them between requests changes no output.
     */
    private static final class Shipped {
        private static volatile Tables tables;
        private static final java.util.Map<String, MachineProfile> PROFILES = new java.util.concurrent.ConcurrentHashMap<>();

        static boolean covers(Options o) {
            return o.tables().isEmpty() && !ProfileLoader.isPath(o.machine()) && o.offsets().isEmpty() && !o.newOffsets()
                    && o.control().map(c -> !gcnc.machine.ControlLoader.isPath(c)).orElse(true);
        }

        static Tables tables() throws TableException {
            Tables t = tables;
            if (t == null) {
                t = Tables.load(TableSource.builtIn());
                tables = t;
            }
            return t;
        }

        static MachineProfile profile(Options o, Tables t) throws TableException {
            String key = o.machine() + "\0" + o.control().orElse("");
            MachineProfile p = PROFILES.get(key);
            if (p == null) { // a name gcnc does not ship fails here every time, with its message
                p = ProfileLoader.load(o.machine(), TableSource.builtIn(), t, o.control().orElse(null));
                PROFILES.put(key, p);
            }
            return p;
        }
    }

    public Options options() {
        return options;
    }

    /** The same tables and machine in another dialect. */
    public Session withDialect(gcnc.galil.Dialect.Kind dialect) {
        return new Session(options.withDialect(dialect), tables, profile, programs);
    }

    /** The same tables and machine with this blank (a blank's default stick-out comes from the profile, so it is given after opening). */
    public Session withStock(StockSize blank) {
        return new Session(options.withStock(blank), tables, profile, programs);
    }

    /**
     * The same tables and options with another machine profile, already loaded (the studio's
     * Configure: a profile edited in memory, to see what it changes before it is saved).
     */
    public Session withProfile(MachineProfile edited) {
        return new Session(options, tables, java.util.Objects.requireNonNull(edited), programs);
    }

    /** The same session looking for called programs ({@code O1000.nc}, {@code 1000.nc}) in {@code folder}. */
    public Session withPrograms(Optional<Path> folder) {
        return new Session(options, tables, profile, folder);
    }

    public Tables tables() {
        return tables;
    }

    public MachineProfile profile() {
        return profile;
    }

    /** The catalogue of diagnostic codes (errors.csv) of these tables, for SARIF's rules and explanations. */
    public CodeTable codes() throws TableException {
        return CodeTable.load(options.source());
    }

    /** How a simulation starts: the blank given, else (in {@link Compiler}) the program's header, else the profile's. */
    public SimOptions simulation() {
        return options.stock().map(SimOptions.defaults()::withStock).orElse(SimOptions.defaults());
    }

    /** Parse and every check: no output, no simulation. */
    public Compiler.Result check(Reader program) throws IOException {
        // the blank, if one was given, places the work zero (work.G54 = face); nothing is simulated
        return waived(Compiler.check(program, checkSettings()), false);
    }

    /** {@link #check(Reader)}, publishing what it saw to {@code observer} (the hover's modal states). */
    public Compiler.Result check(Reader program, CompileObserver observer) throws IOException {
        return waived(Compiler.check(program, checkSettings(), null, observer), false);
    }

    /** What {@link #check} runs with (also {@link ModalStates}, which reads the blocks as a check does). */
    Compiler.Settings checkSettings() {
        return settings(options.stock().map(b -> simulation()), false);
    }

    /**
     * Check, and hand each checked block on as the control runs it (gcnc path: every move after the
     * cycles, corners, nose compensation, calls and macros); no output, no simulation.
     */
    public Compiler.Result path(Reader program, java.util.function.Consumer<gcnc.ir.CheckedBlock> each) throws IOException {
        return waived(Compiler.check(program, checkSettings(), each), false);
    }

    /** Check, translate and simulate (with {@code simulation}, or not at all when empty); the DMC instructions go to {@code out}. */
    public Compiler.Result compile(Reader program, Optional<SimOptions> simulation, boolean inlineSourceMap,
                                   java.util.function.Consumer<gcnc.dmc.Instruction> out) throws IOException {
        return waived(Compiler.compile(program, settings(simulation, inlineSourceMap), out), true);
    }

    /**
     * {@link #compile(Reader, Optional, boolean, java.util.function.Consumer)}, publishing what it saw to
     * {@code observer} (gcnc run's and the studio's views of the program they send: CompileObserver).
     */
    public Compiler.Result compile(Reader program, Optional<SimOptions> simulation, boolean inlineSourceMap,
                                   java.util.function.Consumer<gcnc.dmc.Instruction> out, CompileObserver observer)
            throws IOException {
        return waived(Compiler.compile(program, settings(simulation, inlineSourceMap), out, observer), true);
    }

    /**
     * The compile-to-file wiring every front end shares ({@code gcnc compile}, {@code gcnc run}, the
     * studio, the Gradle plugin): {@code program} compiled into {@code outputs}, whose maps name
     * {@code sourceName} ({@code source}: its SHA-256; null for standard input), through the sink
     * the dialect and form call for (the thesis's format has no form; else the form {@code asked},
     * or the one that fits the profile's controller). After a clean compile the form is decided and
     * what does not fit is reported (E238, E239, E243). Nothing is put in place: the caller reports,
     * then {@link FormOutputs#commit()}s when the result is clean.
     */
    public Compiler.Result compileInto(FormOutputs outputs, String sourceName, Path source, Reader program,
                                       Optional<SimOptions> simulation, boolean inlineSourceMap, Optional<Form> asked,
                                       boolean exactStop, CompileObserver observer) throws IOException {
        outputs.mapSource(sourceName, source);
        java.util.function.Consumer<gcnc.dmc.Instruction> sink = options.dialect() == gcnc.galil.Dialect.Kind.THESIS ? outputs.programSink()
                : outputs.sink(asked, profile.controllerLimits());
        Compiler.Settings s = settings(simulation, inlineSourceMap);
        Compiler.Result r = waived(Compiler.compile(program, exactStop ? s.withExactStop() : s, sink, observer), true);
        if (r.ok()) {
            outputs.finish(r.diagnostics());
        }
        return r;
    }

    /** Check, translate and simulate a program file as the command line's {@code compile} does, output discarded. */
    public Compiler.Result compile(Path program) throws IOException {
        Path folder = program.toAbsolutePath().getParent();
        try (Reader in = Files.newBufferedReader(program)) {
            return withPrograms(Optional.ofNullable(folder)).compile(in, Optional.of(simulation()), false, line -> { });
        }
    }

    /**
     * A program's text as every front end reads it: UTF-8, and a byte that is not UTF-8 becomes
     * U+FFFD, which the parser then reports at its line and column (no front end fails on it alone).
     */
    public static Reader decode(java.io.InputStream in) {
        return new java.io.BufferedReader(new java.io.InputStreamReader(in,
                java.nio.charset.StandardCharsets.UTF_8.newDecoder()
                        .onMalformedInput(java.nio.charset.CodingErrorAction.REPLACE)
                        .onUnmappableCharacter(java.nio.charset.CodingErrorAction.REPLACE)), 1 << 16);
    }

    /**
     * Check, translate and simulate with every motion stopped at its end whatever the profile says: what
     * {@code gcnc run} sends for now, since it follows a program sequence by sequence (docs/run.md).
     */
    public Compiler.Result compileExactStop(Reader program, Optional<SimOptions> simulation,
                                            java.util.function.Consumer<gcnc.dmc.Instruction> out) throws IOException {
        return compileExactStop(program, simulation, out, CompileObserver.NONE);
    }

    /** {@link #compileExactStop(Reader, Optional, java.util.function.Consumer)}, publishing what it saw to {@code observer}. */
    public Compiler.Result compileExactStop(Reader program, Optional<SimOptions> simulation,
                                            java.util.function.Consumer<gcnc.dmc.Instruction> out, CompileObserver observer)
            throws IOException {
        return waived(Compiler.compile(program, settings(simulation, false).withExactStop(), out, observer), true);
    }

    /**
     * The program's waivers ({@code (GCNC ALLOW E642: reason)}, gcnc.diag.Waivers) applied once its
     * findings are final: here, so that every front end reports them the same ({@code translated}:
     * the run translated the program, so a waiver of a backend or simulator code is judged too).
     */
    private static Compiler.Result waived(Compiler.Result r, boolean translated) {
        r.diagnostics().waive(translated);
        return r;
    }

    private Compiler.Settings settings(Optional<SimOptions> simulation, boolean inlineSourceMap) {
        Compiler.Settings s = new Compiler.Settings(tables, profile, options.dialect(), simulation, inlineSourceMap);
        return programs.map(s::withPrograms).orElse(s);
    }
}
