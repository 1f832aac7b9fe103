package gcnc.cli;

import gcnc.galil.Dialect;
import picocli.CommandLine.Option;

/** {@code --dialect}: which Galil program to write, parsed here once into a {@link Dialect.Kind}. */
final class DialectOptions {
    @Option(names = "--dialect", paramLabel = "galil|thesis", defaultValue = "galil",
            description = "galil (default): a standalone DMC program; thesis: the thesis's Table 5.2 directives.")
    Dialect.Kind dialect;

    Dialect.Kind kind() {
        return dialect;
    }

    /** The name as the user writes it, for messages. */
    String name() {
        return dialect.label();
    }

    /** The thesis dialect is a historical record, not a runnable program; compile does not simulate it. */
    boolean simulatedByDefault() {
        return dialect == Dialect.Kind.GALIL;
    }
}
