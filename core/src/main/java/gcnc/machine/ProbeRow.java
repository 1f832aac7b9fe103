package gcnc.machine;

import java.util.Optional;

/**
 * The facts about a Galil that {@code gcnc controller probe} checks on a real unit, each by a stable id
 * (the key of its row in the probe's report, to be joined to tables/galil_conformance.csv), with the
 * reference's words it rests on and whether {@code gcnc run} relies on it. A profile that runs on a unit
 * which contradicts a row names the row in {@code galil.deviations} (docs/run.md, "The probe report").
 */
public enum ProbeRow {
    REVISION("rv-revision", "COMALL ^R^V: \"causes the controller to return the firmware revision information\""
            + " (example DMC4143 Rev 1.1a1)", Reliance.ALWAYS),
    ECHO_SERIAL("eo-echo-serial", "COMALL EO: \"This command is defaulted to EO1\" (the serial port echoes until"
            + " EO 0; galil_models.csv serial_echo)", Reliance.NEVER),
    ECHO_OFF("eo-zero-stops-echo", "COMALL EO: n = 0 \"Echo Off\"", Reliance.SERIAL),
    NO_ECHO_ETHERNET("eo-no-echo-ethernet", "COMALL EO: \"The ethernet port will not echo commands\"",
            Reliance.ETHERNET),
    EO_SERIAL_ONLY("eo-serial-only", "COMALL EO: \"The EO command is accepted over the serial port only\"",
            Reliance.NEVER),
    CF_DEFAULT_SERIAL("cf-default-serial", "COMALL CF: default S (\"m=S is Main serial port\"); _CF \"contains the"
            + " decimal value of the ASCII letter\"", Reliance.NEVER),
    CF_THIS_PORT("cf-i-this-port", "COMALL CF: I \"Set the port that sent the command as the unsolicited message"
            + " port\"", Reliance.ALWAYS),
    TC1_TEXT("tc1-code-text", "COMALL TC: n = 1 \"Return the numerical code and human-readable message\""
            + " (example GF32 then TC1: 1 Unrecognized command)", Reliance.ALWAYS),
    NOT_IN_TERMINAL("wt-not-in-terminal", "COMALL WT: \"Not Valid in terminal\"; TC 2 \"Command only valid from"
            + " program\"", Reliance.NEVER),
    CS_CLEARS_BUFFER("cs-clears-buffer", "COMALL CS: \"will remove VP, CR or LI commands stored in a motion"
            + " sequence\"; LI: \"511 returned means the buffer is empty\"", Reliance.ALWAYS),
    LIMITS_READABLE("lf-lr-readable", "COMALL _LF/_LR: 1 when the switch state will allow motion, 0 when not",
            Reliance.ALWAYS),
    NO_SMOOTHING("it-no-smoothing", "COMALL IT: default 1 = \"no filtering\"; \"also filters the individual axes"
            + " during Vector Mode\" (the simulator verifies corners and times without it)", Reliance.ALWAYS),
    CS_FROM_ZERO("cs-from-zero", "DMC-40x0 User Manual p.86: _CS \"returns number of the segment in the sequence,"
            + " starting at zero\"; during the first segment _CS is 0", Reliance.ALWAYS),
    AVS_FROM_START("avs-from-start", "COMALL AV: \"_AVS contains the vector distance from the start of the"
            + " sequence\"", Reliance.ALWAYS),
    AV_RELATIVE("av-relative", "COMALL AV: \"The distance is measured from the start of a coordinated move"
            + " sequence or from the last AV command\"", Reliance.AV);

    /** When {@code gcnc run} relies on a row. */
    public enum Reliance {
        /** Every run. */
        ALWAYS,
        /** A run over a serial port. */
        SERIAL,
        /** A run over Ethernet. */
        ETHERNET,
        /** A program that waits with AV (the program form's on-the-fly outputs and speed steps). */
        AV,
        /** No run: the sender copes either way (a fact the probe reports for the table). */
        NEVER
    }

    private final String id;
    private final String reference;
    private final Reliance reliance;

    ProbeRow(String id, String reference, Reliance reliance) {
        this.id = id;
        this.reference = reference;
        this.reliance = reliance;
    }

    public String id() {
        return id;
    }

    /** The reference's words the row rests on, with the document. */
    public String reference() {
        return reference;
    }

    /** Whether a run over {@code serial} (else Ethernet) of a program that does ({@code usesAv}) or does not use AV relies on it. */
    public boolean reliedOn(boolean serial, boolean usesAv) {
        return switch (reliance) {
            case ALWAYS -> true;
            case SERIAL -> serial;
            case ETHERNET -> !serial;
            case AV -> usesAv;
            case NEVER -> false;
        };
    }

    public static Optional<ProbeRow> byId(String id) {
        for (ProbeRow r : values()) {
            if (r.id.equals(id)) {
                return Optional.of(r);
            }
        }
        return Optional.empty();
    }
}
