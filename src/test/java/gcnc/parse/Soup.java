package gcnc.parse;

import java.util.Random;

/** Random programs for the fuzz and agreement tests: valid ones and token soup. */
final class Soup {
    private static final String[] INTEGER = {"G", "M", "N", "O", "P", "S", "T", "g", "m", "n", "o", "p", "s", "t"};
    private static final String[] DECIMAL = {"I", "K", "R", "U", "W", "X", "Z", "i", "k", "r", "u", "w", "x", "z"};
    private static final String[] LAYOUT = {" ", "  ", "\t", "", "(c)", " (a b) ", ";x", "%", "\n", "\r\n", "\r",
        "(line\nbreak)", "(", ")", "((", "$", "é", "\u0000", "\uD83D\uDE00", "Y", "b", "5", ".", "+", "-", "..",
        "1.2.3", "-1.5", "+2", "07", ".5", ":", "#", "[", "\"", "\uFEFF"};

    private final Random random;

    Soup(long seed) {
        this.random = new Random(seed);
    }

    private String digits(int min) {
        int n = min + random.nextInt(4);
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < n; i++) {
            sb.append((char) ('0' + random.nextInt(10)));
        }
        return sb.toString();
    }

    private String unsigned() {
        switch (random.nextInt(4)) {
            case 0: return digits(1);
            case 1: return digits(1) + ".";
            case 2: return digits(1) + "." + digits(0);
            default: return "." + digits(1);
        }
    }

    /** One word the language accepts. */
    String validWord() {
        switch (random.nextInt(3)) {
            case 0: return INTEGER[random.nextInt(INTEGER.length)] + digits(1);
            case 1: return (random.nextBoolean() ? "F" : "f") + unsigned();
            default:
                String sign = new String[] {"", "+", "-"}[random.nextInt(3)];
                return DECIMAL[random.nextInt(DECIMAL.length)] + sign + unsigned();
        }
    }

    /** A program of valid words, spacing, comments (some over several lines) and line ends. */
    String validProgram(int lines) {
        StringBuilder sb = new StringBuilder();
        String[] gaps = {" ", "\t", "  ", " (note) ", "(x)"};
        for (int l = 0; l < lines; l++) {
            int words = random.nextInt(6);
            for (int w = 0; w < words; w++) {
                sb.append(random.nextInt(4) == 0 ? "" : gaps[random.nextInt(gaps.length)]);
                sb.append(validWord());
            }
            switch (random.nextInt(8)) {
                case 0: sb.append(" ; end"); break;
                case 1: sb.append(" (spans\nlines) "); break;
                case 2: sb.append("%"); break;
                default: break;
            }
            sb.append(random.nextBoolean() ? "\n" : "\r\n");
        }
        return sb.toString();
    }

    /** Valid words mixed with every kind of junk the lexer must survive. */
    String tokenSoup(int pieces) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < pieces; i++) {
            if (random.nextInt(3) == 0) {
                sb.append(LAYOUT[random.nextInt(LAYOUT.length)]);
            } else {
                String w = validWord();
                sb.append(random.nextInt(8) == 0 ? w.substring(0, 1) : w);
            }
        }
        return sb.toString();
    }

    /** A valid program with one random insertion, deletion or doubling in about half its lines. */
    String mutatedProgram(int lines) {
        StringBuilder out = new StringBuilder();
        for (String line : validProgram(lines).split("\n", -1)) {
            StringBuilder sb = new StringBuilder(line);
            if (random.nextBoolean() && sb.length() > 0) {
                int at = random.nextInt(sb.length());
                switch (random.nextInt(3)) {
                    case 0: sb.insert(at, LAYOUT[random.nextInt(LAYOUT.length)]); break;
                    case 1: sb.deleteCharAt(at); break;
                    default: sb.insert(at, sb.charAt(at)); break;
                }
            }
            out.append(sb).append('\n');
        }
        return out.toString();
    }

    /** Arbitrary characters, mostly ASCII. */
    String bytes(int n) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < n; i++) {
            sb.append((char) (random.nextInt(10) == 0 ? random.nextInt(0x10000) : random.nextInt(128)));
        }
        return sb.toString();
    }
}
