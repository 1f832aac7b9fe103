package gcnc.cli;

import picocli.CommandLine.Option;

/** {@code --dialect}: which Galil program to write. */
final class DialectOptions {
    enum Name {
        /** A standalone DMC program a controller can run (default). */
        GALIL,
        /** The thesis's directives, reproducing its Table 5.2 byte for byte. */
        THESIS
    }

    @Option(names = "--dialect", paramLabel = "galil|thesis", defaultValue = "galil",
            description = "galil (default): a standalone DMC program; thesis: the thesis's Table 5.2 directives.")
    Name dialect;

    String name() {
        return dialect.name().toLowerCase(java.util.Locale.ROOT);
    }

    /** The thesis dialect is a historical record, not a runnable program; compile does not simulate it. */
    boolean simulatedByDefault() {
        return dialect == Name.GALIL;
    }
}
