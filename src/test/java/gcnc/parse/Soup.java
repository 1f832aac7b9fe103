package gcnc.parse;

import java.util.Random;

/** Random programs for the fuzz and agreement tests: valid ones and token soup. */
final class Soup {
    private static final String[] INTEGER = {"G", "M", "N", "O", "S", "T", "g", "m", "n", "o", "s", "t"};
    private static final String[] DECIMAL = {"A", "B", "C", "D", "E", "H", "I", "J", "K", "L", "P", "Q", "R", "U",
        "V", "W", "X", "Y", "Z", "a", "b", "c", "d", "e", "h", "i", "j", "k", "l", "p", "q", "r", "u", "v", "w", "x",
        "y", "z"};
    private static final String[] LAYOUT = {" ", "  ", "\t", "", "(c)", " (a b) ", ";x", "%", "\n", "\r\n", "\r",
        "(line\nbreak)", "(", ")", "((", "$", "é", "\u0000", "\uD83D\uDE00", "Y", "b", "5", ".", "+", "-", "..",
        "1.2.3", "-1.5", "+2", "07", ".5", ":", ":12", ":1.5", "/", "/3", "/0", "#", "#501=2.", "[", "]", "[#1+2]",
        "ab", "roughing pass", "\"", "\uFEFF"};

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

    /** One word the language accepts; now and then with a space after its letter ('G 01', ', C1.'). */
    String validWord() {
        String w;
        switch (random.nextInt(3)) {
            case 0:
                w = (random.nextInt(20) == 0 ? ":" : INTEGER[random.nextInt(INTEGER.length)]) + digits(1);
                break;
            case 1:
                w = (random.nextBoolean() ? "F" : "f") + unsigned();
                break;
            default:
                String sign = new String[] {"", "+", "-"}[random.nextInt(3)];
                String comma = random.nextInt(10) == 0 ? "," + "CRAcra".charAt(random.nextInt(6)) : null;
                w = (comma != null ? comma : DECIMAL[random.nextInt(DECIMAL.length)]) + sign + unsigned();
                break;
        }
        int letter = w.startsWith(",") ? 2 : 1;
        return random.nextInt(8) == 0 && !w.startsWith(":") ? w.substring(0, letter) + " " + w.substring(letter) : w;
    }

    /** A program of valid words, spacing, comments (some over several lines) and line ends. */
    String validProgram(int lines) {
        StringBuilder sb = new StringBuilder();
        String[] gaps = {" ", "\t", "  ", " (note) ", "(x)"};
        for (int l = 0; l < lines; l++) {
            int words = random.nextInt(6);
            int slash = random.nextInt(8); // 0: block delete first, 1: after a first N word, 2: mid-block
            if (slash == 0) {
                sb.append(random.nextBoolean() ? " " : "").append(blockDelete());
            }
            for (int w = 0; w < words; w++) {
                sb.append(random.nextInt(4) == 0 ? "" : gaps[random.nextInt(gaps.length)]);
                if (w == 1 && slash == 2) {
                    sb.append(blockDelete()); // a '/' in the middle: the rest of the block
                }
                if (w == 0 && slash == 1) {
                    sb.append(random.nextBoolean() ? "N" : "n").append(digits(1))
                            .append(random.nextBoolean() ? " " : "").append(blockDelete());
                } else {
                    sb.append(validWord());
                }
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

    /** A block delete mark: '/' or '/' and a level 1-9. */
    private String blockDelete() {
        return random.nextBoolean() ? "/" : "/" + (1 + random.nextInt(9));
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
