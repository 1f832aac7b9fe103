package gcnc.controller;

/**
 * The Galil error codes (TC) the virtual controller sets, with the text {@code TC1} answers. Codes and
 * texts are Galil's (command reference, TC; the same table in the drivers named in
 * docs/virtual-controller.md): a sender that reads {@code TC1} from this controller reads what a real one says.
 */
enum Tc {
    NONE(0, "No error"),
    UNRECOGNIZED(1, "Unrecognized command"),
    ONLY_IN_PROGRAM(2, "Command only valid from program"),
    NOT_IN_PROGRAM(3, "Command not valid in program"),
    OPERAND(4, "Operand error"),
    RANGE(6, "Number out of range"),
    WHILE_RUNNING(7, "Command not valid while running"),
    VARIABLE(9, "Variable error"),
    UNDEFINED_LABEL(10, "Empty program line or undefined label"),
    SUBROUTINE_DEPTH(12, "Subroutine more than 16 deep"),
    DL_WHILE_RUNNING(17, "ED, BN and DL not valid while program running"),
    MOTOR_OFF(20, "Begin not valid with motor off"),
    BEGIN_WHILE_RUNNING(21, "Begin not valid while running"),
    LIMIT_SWITCH(22, "Begin not possible due to Limit Switch"),
    NO_SEQUENCE(24, "Begin not valid because no sequence defined"),
    S_OPERAND(28, "S operand not valid"),
    SEGMENT_TOO_SHORT(30, "Sequence Segment Too Short"),
    SEQUENCE_TOO_LONG(31, "Total move distance in a sequence > 2 billion"),
    BUFFER_FULL(32, "Segment buffer full"),
    MISSING_QUOTE(52, "Missing \" or string too long"),
    BAD_INDEX(56, "Array index invalid or out of range"),
    BAD_FUNCTION(57, "Bad function or array"),
    PARENTHESES(59, "Mismatched parentheses"),
    DOWNLOAD(60, "Download error - line too long or too many lines"),
    BAD_LABEL(61, "Duplicate or bad label"),
    TOO_MANY_LABELS(62, "Too many labels"),
    IF_WITHOUT_ENDIF(63, "IF statement without ENDIF"),
    ARRAY_SPACE(66, "Array space full"),
    TOO_MANY_VARIABLES(67, "Too many arrays or variables");

    final int code;
    final String text;

    Tc(int code, String text) {
        this.code = code;
        this.text = text;
    }
}
