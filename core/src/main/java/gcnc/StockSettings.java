package gcnc;

import gcnc.Compiler.Settings;
import gcnc.machine.MachineProfile;
import gcnc.sim.SimOptions;
import java.io.IOException;
import java.util.Optional;

/**
 * A run's settings placed on its blank, for {@link Compiler}: the blank the run is given moves the
 * work offsets a shop sets on the blank's face, and without one the program's stock header
 * ({@link Compiler#withStockHeader(String, MachineProfile, SimOptions)}) gives the simulation its blank.
 */
final class StockSettings {
    private StockSettings() {
    }

    /** The longest first line read for a stock header; the program is read once, from the start. */
    static final int HEADER_PEEK = 1 << 16;

    /**
     * The blank from the program's stock header (an EMCO-style first-line comment, {@code (length
     * diameter ...)}), when the simulation has none given and the profile reads headers: the same
     * for the command line, the JUnit fixtures and any other front end. The first line is peeked
     * at and the program is then read from its start.
     */
    static Settings withStockHeader(java.io.BufferedReader in, Settings settings) throws IOException {
        if (settings.simulation().isEmpty() || settings.simulation().get().stock().isPresent()) {
            return settings;
        }
        in.mark(HEADER_PEEK);
        StringBuilder first = new StringBuilder();
        for (int c = in.read(); c >= 0 && c != '\n' && c != '\r' && first.length() < HEADER_PEEK - 1; c = in.read()) {
            first.append((char) c);
        }
        in.reset();
        SimOptions o = Compiler.withStockHeader(first.toString(), settings.profile(), settings.simulation().get());
        return new Settings(settings.tables(), settings.profile(), settings.dialect(), Optional.of(o),
                settings.inlineSourceMap(), settings.programs(), settings.exactStop());
    }

    /**
     * The machine with the work offsets a shop sets on the blank's face ({@code work.G54 = 0, face})
     * moved to the face of the blank the simulation is given ({@code --stock D,L,S}): the program's
     * Z0 is where the operator would have touched off.
     */
    static Settings onTheBlank(Settings s) {
        Optional<gcnc.sim.StockSize> blank = s.simulation().flatMap(SimOptions::stock);
        if (blank.isEmpty()) {
            return s;
        }
        MachineProfile p = s.profile().withStickout(blank.get().stickout());
        return p == s.profile() ? s
                : new Settings(s.tables(), p, s.dialect(), s.simulation(), s.inlineSourceMap(), s.programs(), s.exactStop());
    }
}
