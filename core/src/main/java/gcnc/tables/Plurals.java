package gcnc.tables;

import java.text.ChoiceFormat;
import java.util.List;

/**
 * Plurals in messages, the {@link ChoiceFormat} way: a template says
 * {@code {0,choice,1#1 later block has|1<{0} later blocks have}} and the count picks the form, in
 * English and in Spanish alike (tables/errors.csv, tables/phrases.csv, the command line's
 * Phrases*.properties). The choice is made here, before MessageFormat fills the placeholders, so
 * that every argument, the count too, is shown exactly as the diagnostic gives it (MessageFormat
 * would print a number given to a choice as 10,000). A CSV field holds no comma, so there the
 * choice is written with semicolons, {@code {0;choice;1#1 block|1<{0} blocks}}: the same pattern.
 */
public final class Plurals {
    private Plurals() {
    }

    /**
     * {@code template} with each {@code {n,choice,...}} replaced by the form its argument picks;
     * an argument that is not a number picks the last form (the plural), a template without a
     * choice comes back as it is. A malformed choice is an IllegalArgumentException, as
     * MessageFormat's own.
     */
    public static String choose(String template, List<String> args) {
        java.util.regex.Matcher m = CHOICE.matcher(template);
        if (!m.find()) {
            return template;
        }
        StringBuilder out = new StringBuilder();
        int from = 0;
        do {
            int index = Integer.parseInt(m.group(1));
            int close = closing(template, m.end());
            ChoiceFormat choice = new ChoiceFormat(template.substring(m.end(), close));
            out.append(template, from, m.start()).append(choice.format(number(index < args.size() ? args.get(index) : "")));
            from = close + 1;
        } while (m.find(from));
        return out.append(template.substring(from)).toString();
    }

    /** The start of a choice: {@code {0,choice,} or, in a CSV field, {@code {0;choice;}. */
    private static final java.util.regex.Pattern CHOICE = java.util.regex.Pattern.compile("\\{(\\d+)([,;])choice\\2");

    /** The index of the brace that closes a choice starting at {@code from} (its forms may hold {0}). */
    private static int closing(String s, int from) {
        int depth = 0;
        for (int i = from; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '{') {
                depth++;
            } else if (c == '}') {
                if (depth == 0) {
                    return i;
                }
                depth--;
            }
        }
        throw new IllegalArgumentException("unclosed choice in: " + s);
    }

    private static double number(String arg) {
        try {
            return Double.parseDouble(arg.trim());
        } catch (NumberFormatException e) {
            return Double.MAX_VALUE;
        }
    }
}
