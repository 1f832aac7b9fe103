package gcnc.tables;

/** A row of Table 6: a word's value type and range as programmed. */
public record ParameterLimit(char word, boolean mayBeNegative, boolean integer, double lower, double upper) {
}
