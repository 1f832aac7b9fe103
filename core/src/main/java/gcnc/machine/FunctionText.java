package gcnc.machine;

import java.util.Locale;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

/**
 * What a G or M word does on one control, as its row of {@code g_codes.csv} or {@code m_codes.csv}
 * says: the code as the control writes it, the text in English and Spanish, the modal group, and
 * for a G code the words it takes, for an M code when it acts in the block. One reading for every
 * front end that shows it: the studio's hover, {@code gcnc explain G71 --machine haas}.
 *
 * @param letter  'G' or 'M'
 * @param code    the number (G01 = 1)
 * @param known   whether the control's table has the code (false: nothing else is filled)
 * @param role    what the code does in gcnc's terms (the table's {@code function} column), lower case
 * @param words   a G code's parameter words as the table lists them ("X Z U W"), "" for none, "*" when the
 *                table leaves them to the checker (cycles, modal codes); "" for an M
 * @param moment  an M code's moment (1 start of block, 0 during, 99 end of block); -1 for a G
 */
public record FunctionText(char letter, int code, String control, boolean known, String english, String spanish,
                           int group, String role, String words, int moment) {
    private static final Pattern WORD = Pattern.compile("([GgMm])\\s*0*([0-9]{1,3})");

    /** The code as the control writes it: G01, M30, G71. */
    public String name() {
        return letter + (code < 10 ? "0" : "") + code;
    }

    /** A modal G code (group 0 is one-shot); an M code's group is gcnc's "one per block" group. */
    public boolean modal() {
        return letter == 'G' && group != 0;
    }

    /** The text in {@code lang}. */
    public String text(gcnc.tables.ErrorMessages.Lang lang) {
        return lang == gcnc.tables.ErrorMessages.Lang.ES ? spanish : english;
    }

    /** Whether {@code word} reads as a G or M word ({@code G71}, {@code g1}, {@code M 00}). */
    public static boolean isWord(String word) {
        return WORD.matcher(word.strip()).matches();
    }

    /** The function {@code word} names on {@code control}; empty when the word is not a G or M word. */
    public static Optional<FunctionText> of(Control control, String word) {
        Matcher m = WORD.matcher(word.strip());
        if (!m.matches()) {
            return Optional.empty();
        }
        char letter = Character.toUpperCase(m.group(1).charAt(0));
        int code = Integer.parseInt(m.group(2));
        if (letter == 'G') {
            GFunction g = control.g().get(code);
            if (g == null) {
                return Optional.of(unknown(letter, code, control));
            }
            String words = g.words() == null ? "*" : g.words().stream().map(p -> p.name())
                    .collect(Collectors.joining(" "));
            return Optional.of(new FunctionText(letter, code, control.name(), true, g.english(), g.spanish(), g.group(),
                    g.role().name().toLowerCase(Locale.ROOT), words, -1));
        }
        MFunction f = control.m().get(code);
        if (f == null) {
            return Optional.of(unknown(letter, code, control));
        }
        return Optional.of(new FunctionText(letter, code, control.name(), true, f.english(), f.spanish(), f.group(),
                f.role().name().toLowerCase(Locale.ROOT), "", f.moment()));
    }

    private static FunctionText unknown(char letter, int code, Control control) {
        return new FunctionText(letter, code, control.name(), false, "", "", 0, "", "", -1);
    }
}
