package gcnc.controller;

/** A command the controller rejects: it answers {@code ?} and {@code TC1} then gives {@link #tc}. */
final class GalilException extends Exception {
    final Tc tc;

    GalilException(Tc tc) {
        super(tc.code + " " + tc.text, null, false, false);
        this.tc = tc;
    }
}
