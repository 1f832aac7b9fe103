package gcnc.controller;

import java.util.Locale;

/**
 * Galil's arithmetic and logical expressions, as in arguments, conditions ({@code JP #A,x<5}, {@code IF})
 * and assignments. The controller "does not obey standard operator precedence ... the controller follows
 * left-to-right precedence" (DMC-40x0 command reference, Parentheses): {@code 1+2*3} is 9. Operators
 * {@code + - * / %}, {@code & |} (logical on non-zero), comparisons {@code < > = <= >= <>} (1 or 0);
 * operands: numbers, {@code $hex}, variables, {@code name[index]}, {@code _XXa} operands,
 * {@code @FN[x]} functions, parentheses.
 */
final class Expressions {
    /** Where the names in an expression get their values. */
    interface Scope {
        double variable(String name) throws GalilException;

        double array(String name, int index) throws GalilException;

        /** An operand without its underscore: "LMS", "TPX", "XQ0", "TC". */
        double operand(String name) throws GalilException;

        /** {@code @IN[n]}, {@code @OUT[n]}. */
        double io(String function, int n) throws GalilException;
    }

    private final String s;
    private final Scope scope;
    private int at;

    private Expressions(String s, Scope scope) {
        this.s = s;
        this.scope = scope;
    }

    /** The value of the whole text; TC 4 (operand error) when anything is left over. */
    static double eval(String text, Scope scope) throws GalilException {
        Expressions e = new Expressions(text, scope);
        double v = e.expression();
        e.blanks();
        if (e.at != e.s.length()) {
            throw new GalilException(e.s.charAt(e.at) == ')' ? Tc.PARENTHESES : Tc.OPERAND);
        }
        return v;
    }

    private double expression() throws GalilException {
        double v = unary();
        while (true) {
            blanks();
            if (at >= s.length()) {
                return v;
            }
            String op = operator();
            if (op == null) {
                return v;
            }
            double r = unary();
            v = apply(op, v, r);
        }
    }

    private static double apply(String op, double a, double b) throws GalilException {
        return switch (op) {
            case "+" -> a + b;
            case "-" -> a - b;
            case "*" -> a * b;
            case "/" -> {
                if (b == 0) {
                    throw new GalilException(Tc.RANGE);
                }
                yield a / b;
            }
            case "%" -> {
                if (b == 0) {
                    throw new GalilException(Tc.RANGE);
                }
                yield a % b;
            }
            case "&" -> a != 0 && b != 0 ? 1 : 0;
            case "|" -> a != 0 || b != 0 ? 1 : 0;
            case "<" -> a < b ? 1 : 0;
            case ">" -> a > b ? 1 : 0;
            case "=" -> a == b ? 1 : 0;
            case "<=" -> a <= b ? 1 : 0;
            case ">=" -> a >= b ? 1 : 0;
            default -> a != b ? 1 : 0; // "<>"
        };
    }

    private String operator() {
        char c = s.charAt(at);
        if (c == '<' || c == '>') {
            at++;
            if (at < s.length() && (s.charAt(at) == '=' || c == '<' && s.charAt(at) == '>')) {
                return "" + c + s.charAt(at++);
            }
            return "" + c;
        }
        if ("+-*/%&|=".indexOf(c) >= 0) {
            at++;
            return "" + c;
        }
        return null;
    }

    private double unary() throws GalilException {
        blanks();
        if (at < s.length() && (s.charAt(at) == '-' || s.charAt(at) == '+')) {
            boolean minus = s.charAt(at++) == '-';
            double v = unary();
            return minus ? -v : v;
        }
        return primary();
    }

    private double primary() throws GalilException {
        blanks();
        if (at >= s.length()) {
            throw new GalilException(Tc.OPERAND);
        }
        char c = s.charAt(at);
        if (c == '(') {
            return enclosed(')', Tc.PARENTHESES);
        }
        if (Character.isDigit(c) || c == '.') {
            int from = at;
            while (at < s.length() && (Character.isDigit(s.charAt(at)) || s.charAt(at) == '.')) {
                at++;
            }
            try {
                return Double.parseDouble(s.substring(from, at));
            } catch (NumberFormatException e) {
                throw new GalilException(Tc.OPERAND);
            }
        }
        if (c == '$') {
            int from = ++at;
            while (at < s.length() && Character.digit(s.charAt(at), 16) >= 0) {
                at++;
            }
            if (from == at) {
                throw new GalilException(Tc.OPERAND);
            }
            return Long.parseLong(s.substring(from, at), 16);
        }
        if (c == '_') {
            at++;
            return scope.operand(name().toUpperCase(Locale.ROOT));
        }
        if (c == '@') {
            at++;
            String fn = name().toUpperCase(Locale.ROOT);
            double x = bracket();
            return function(fn, x);
        }
        if (Character.isLetter(c)) {
            String n = name();
            blanks();
            if (at < s.length() && s.charAt(at) == '[') {
                double i = bracket();
                if (i != Math.rint(i) || i < 0) {
                    throw new GalilException(Tc.BAD_INDEX);
                }
                return scope.array(n, (int) i);
            }
            return scope.variable(n);
        }
        throw new GalilException(Tc.OPERAND);
    }

    private double function(String fn, double x) throws GalilException {
        return switch (fn) {
            case "ABS" -> Math.abs(x);
            case "INT" -> x < 0 ? Math.ceil(x) : Math.floor(x);
            case "FRAC" -> x - (x < 0 ? Math.ceil(x) : Math.floor(x));
            case "RND" -> Math.floor(x + 0.5); // COMALL @RND: 5.5 -> 6, -5.5 -> -5 (halves up)
            case "SQR" -> Math.sqrt(Math.abs(x)); // COMALL @SQR: "If n < 0, the absolute value is taken first"
            case "SIN" -> Math.sin(Math.toRadians(x));
            case "COS" -> Math.cos(Math.toRadians(x));
            case "IN", "OUT" -> scope.io(fn, (int) x);
            default -> throw new GalilException(Tc.BAD_FUNCTION);
        };
    }

    private double bracket() throws GalilException {
        blanks();
        if (at >= s.length() || s.charAt(at) != '[') {
            throw new GalilException(Tc.BAD_FUNCTION);
        }
        return enclosed(']', Tc.BAD_FUNCTION);
    }

    /** After an opening bracket: the expression inside, up to {@code close}; {@code unclosed} without it. */
    private double enclosed(char close, Tc unclosed) throws GalilException {
        at++;
        double v = expression();
        blanks();
        if (at >= s.length() || s.charAt(at) != close) {
            throw new GalilException(unclosed);
        }
        at++;
        return v;
    }

    private String name() throws GalilException {
        int from = at;
        while (at < s.length() && (Character.isLetterOrDigit(s.charAt(at)))) {
            at++;
        }
        if (from == at) {
            throw new GalilException(Tc.OPERAND);
        }
        return s.substring(from, at);
    }

    private void blanks() {
        while (at < s.length() && s.charAt(at) == ' ') {
            at++;
        }
    }
}
