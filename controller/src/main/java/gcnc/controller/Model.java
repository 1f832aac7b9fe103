package gcnc.controller;

import gcnc.machine.GalilModel;
import gcnc.machine.GalilModel.Limit;
import gcnc.machine.GalilModels;
import java.util.Locale;
import java.util.Optional;

/**
 * The Galil the virtual controller is: a row of tables/galil_models.csv ({@link GalilModel}, the table
 * gcnc checks its programs against), so that the controller has exactly the memory and outputs the
 * compiler assumes. A model whose row gives firmware 1.2a figures runs firmware 1.2d (4,000 program
 * lines, 24,000 array elements); one without runs 1.0h (2,000 and 16,000). What {@code ^R^V} answers is
 * the model and that revision, as a Galil writes them ("DMC4040 Rev 1.2d").
 */
public final class Model {
    /** Array names: not in the table (the reference gives no count for these models; 30 assumed). */
    static final int ARRAYS = 30;

    /** The model's row, at the firmware the virtual controller runs. */
    public final GalilModel galil;
    /** The reply to {@code ^R^V}: model and firmware revision. */
    public final String revision;
    final int axes;
    final int outputs;
    final int lines;
    final int lineChars;
    final int labels;
    final int variables;
    final int arrayElements;

    private Model(GalilModel row) {
        this.galil = row.hasFirmware12a() ? row.withFirmware12a() : row;
        this.revision = galil.name().replace("-", "") + " Rev " + (galil.newFirmware() ? "1.2d" : "1.0h");
        this.axes = galil.axes();
        this.outputs = galil.digitalOutputs();
        this.lines = (int) galil.range(Limit.PROGRAM_LINES).max();
        this.lineChars = (int) galil.range(Limit.LINE_LENGTH).max();
        this.labels = (int) galil.range(Limit.LABELS).max();
        this.variables = (int) galil.range(Limit.VARIABLES).max();
        this.arrayElements = (int) galil.range(Limit.ARRAY_ELEMENTS).max();
    }

    /** The model gcnc assumes when a profile names none (DMC-4040). */
    public static Model standard() {
        return named(GalilModels.DEFAULT).orElseThrow();
    }

    /** The model named as the table names it or as a controller's label reads it ("DMC4040", "dmc-4040"). */
    public static Optional<Model> named(String name) {
        String want = squeeze(name);
        return GalilModels.builtIn().all().stream().filter(m -> squeeze(m.name()).equals(want)).findFirst()
                .map(Model::new);
    }

    /** Every model name of the table, for a message. */
    public static String names() {
        StringBuilder b = new StringBuilder();
        for (GalilModel m : GalilModels.builtIn().all()) {
            b.append(b.length() == 0 ? "" : ", ").append(m.name());
        }
        return b.toString();
    }

    private static String squeeze(String s) {
        return s.replace("-", "").toUpperCase(Locale.ROOT);
    }

    @Override
    public String toString() {
        return revision;
    }
}
