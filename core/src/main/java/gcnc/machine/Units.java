package gcnc.machine;

/** Input units: G21 millimetres, G20 inches. */
public enum Units { MM, INCH }
