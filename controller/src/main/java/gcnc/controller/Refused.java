package gcnc.controller;

/**
 * A {@link GalilException} carried through a {@link gcnc.dmc.Command.Visitor} ({@link DmcCommands}), whose
 * methods cannot throw it: {@link DmcCommands#execute} unwraps it and throws the exception it carries.
 */
final class Refused extends RuntimeException {
    final GalilException reason;

    Refused(GalilException reason) {
        super(null, null, false, false);
        this.reason = reason;
    }

    /** The refusal with {@code tc}. */
    static Refused refuse(Tc tc) {
        return new Refused(new GalilException(tc));
    }

    /** A step of a command that may refuse. */
    interface Action {
        void run() throws GalilException;
    }

    /** A value a command reads that may be refused (an unknown variable). */
    interface Value {
        double get() throws GalilException;
    }

    /** Runs {@code a}, its GalilException a Refused; null, the visitor's answer. */
    static Void doing(Action a) {
        try {
            a.run();
        } catch (GalilException e) {
            throw new Refused(e);
        }
        return null;
    }

    /** The value {@code v} reads, its GalilException a Refused. */
    static double reading(Value v) {
        try {
            return v.get();
        } catch (GalilException e) {
            throw new Refused(e);
        }
    }
}
