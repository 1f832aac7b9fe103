package gcnc.flow;

import gcnc.diag.Code;

/**
 * Macro B expressions over a line ({@link MacroCursor}): {@code [ ]} and functions first, then
 * {@code * / MOD}, then {@code + -}; a value is a double, null when vacant (0 in arithmetic);
 * conditions {@code a EQ|NE|GT|GE|LT|LE b}. Variables are read from {@link Variables}: one the
 * machine alone knows is E147; a division by zero or a function outside its domain is E146.
 *
 * <p>Every number a line writes or works out is held to what a Fanuc macro variable holds: 0, or a
 * size from 10^-29 to 10^47 (FANUC 0i/16/18 operator's manual, custom macro, "Range of variable
 * values": past it the control stops with alarm 111, calculated data overflow); past it E683 at the
 * number or the operation. Brackets nest at most five deep (MacroLine.brackets, alarm 118); a run of
 * signs ({@code --#1}) is read in a loop, not by recursion, so no line can overflow the stack.
 */
class MacroExpression extends MacroCursor {
    /** The largest and smallest size of a value other than 0 (alarm 111 outside them). */
    static final double MAX_VALUE = 1e47;
    static final double MIN_VALUE = 1e-29;

    final Variables vars;

    MacroExpression(String s, Variables vars) {
        super(s);
        this.vars = vars;
    }

    boolean bracketedCondition() throws Fault {
        blank();
        expect('[');
        boolean holds = condition();
        expect(']');
        return holds;
    }

    /** {@code a OP b}, OP one of EQ NE GT GE LT LE; a vacant value equals only a vacant one. */
    boolean condition() throws Fault {
        Double a = expr();
        blank();
        int at = i;
        String op = letters();
        Double b = expr();
        blank();
        if (peek() != ']') {
            throw new Fault(Code.E111_MACRO_NOT_SUPPORTED_YET, i, excerpt(i)); // AND/OR of conditions
        }
        switch (op) {
            case "EQ":
                return a == null || b == null ? a == b : Math.abs(a - b) < 1e-9;
            case "NE":
                return a == null || b == null ? a != b : Math.abs(a - b) >= 1e-9;
            case "GT":
                return value(a) > value(b);
            case "GE":
                return value(a) >= value(b);
            case "LT":
                return value(a) < value(b);
            case "LE":
                return value(a) <= value(b);
            default:
                throw syntax(at);
        }
    }

    Double expr() throws Fault {
        blank();
        int start = i;
        Double v = term();
        while (true) {
            blank();
            char c = peek();
            if (c == '+' || c == '-') {
                i++;
                double b = value(term());
                v = held(c == '+' ? value(v) + b : value(v) - b, start);
            } else if (keywordAhead("OR") || keywordAhead("XOR")) {
                throw new Fault(Code.E111_MACRO_NOT_SUPPORTED_YET, i, excerpt(start));
            } else {
                return v;
            }
        }
    }

    Double term() throws Fault {
        blank();
        int start = i;
        Double v = unary();
        while (true) {
            blank();
            char c = peek();
            if (c == '*') {
                i++;
                v = held(value(v) * value(unary()), start);
            } else if (c == '/') {
                i++;
                v = held(value(v) / divisor(start), start);
            } else if (keyword("MOD")) {
                v = held(value(v) % divisor(start), start);
            } else if (keywordAhead("AND")) {
                throw new Fault(Code.E111_MACRO_NOT_SUPPORTED_YET, i, excerpt(start));
            } else {
                return v;
            }
        }
    }

    /** The value a / or MOD divides by: E146 for zero, the term from {@code start} shown (no value comes of it). */
    private double divisor(int start) throws Fault {
        double b = value(unary());
        if (b == 0) {
            throw new Fault(Code.E146_MACRO_NO_VALUE, start, excerpt(start, i));
        }
        return b;
    }

    /** Signs before a value, any number of them: counted in a loop (no recursion, no depth). */
    Double unary() throws Fault {
        boolean negative = false;
        for (blank(); peek() == '-' || peek() == '+'; blank()) {
            negative ^= peek() == '-';
            i++;
        }
        Double v = primary();
        if (v == null || !negative) {
            return v;
        }
        return -v;
    }

    /**
     * {@code v}, when a macro variable can hold it; else E683 at {@code at} (the number or the
     * operation that came to it): a control stops there with alarm 111. NaN and infinities are
     * outside too.
     */
    double held(double v, int at) throws Fault {
        double size = Math.abs(v);
        if (v != 0 && !(size >= MIN_VALUE && size <= MAX_VALUE)) {
            throw new Fault(Code.E683_MACRO_VALUE_RANGE, at, excerpt(at, i), written(v));
        }
        return v + 0.0; // no -0
    }

    /** A value for a message, in any language: six digits and a power of ten; past a double's range "&gt;1.8E+308". */
    static String written(double v) {
        if (Double.isNaN(v)) {
            return "NaN";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? ">1.8E+308" : "<-1.8E+308";
        }
        return new java.math.BigDecimal(v).round(new java.math.MathContext(6)).stripTrailingZeros().toString();
    }

    Double primary() throws Fault {
        blank();
        int at = i;
        char c = peek();
        if (c == '#') {
            i++;
            long n = variable();
            try {
                return vars.read(n);
            } catch (Variables.Refused r) {
                throw new Fault(r.code, at, "#" + n);
            }
        }
        if (c == '[') {
            i++;
            Double v = expr();
            expect(']');
            return v;
        }
        if (Character.isDigit(c) || c == '.') {
            String t = literal();
            try {
                return held(Double.parseDouble(t), at);
            } catch (NumberFormatException e) {
                throw syntax(at);
            }
        }
        if (Character.isLetter(c)) {
            return function(at, letters());
        }
        throw syntax(at);
    }

    /** SIN COS TAN ASIN ACOS ATAN (degrees; ATAN[a]/[b] and ATAN[a,b] give 0 to 360) SQRT ABS ROUND FIX FUP LN EXP. */
    Double function(int at, String name) throws Fault {
        switch (name) {
            case "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "ROUND", "FIX", "FUP", "LN", "EXP":
                break;
            case "BIN", "BCD", "POW", "ADP":
                throw new Fault(Code.E111_MACRO_NOT_SUPPORTED_YET, at, excerpt(at));
            default:
                throw syntax(at);
        }
        blank();
        expect('[');
        double a = value(expr());
        blank();
        Double b = null;
        if (name.equals("ATAN") && peek() == ',') {
            i++;
            b = value(expr());
            blank();
        }
        expect(']');
        if (name.equals("ATAN") && b == null) {
            int save = i;
            blank();
            if (peek() == '/' && i + 1 < s.length()) {
                i++;
                blank();
                if (peek() == '[') {
                    i++;
                    b = value(expr());
                    expect(']');
                } else {
                    i = save;
                }
            } else {
                i = save;
            }
        }
        double r = switch (name) {
            case "SIN" -> Math.sin(Math.toRadians(a));
            case "COS" -> Math.cos(Math.toRadians(a));
            case "TAN" -> Math.tan(Math.toRadians(a));
            case "ASIN" -> Math.toDegrees(Math.asin(a));
            case "ACOS" -> Math.toDegrees(Math.acos(a));
            case "ATAN" -> b == null ? Math.toDegrees(Math.atan(a)) : (Math.toDegrees(Math.atan2(a, b)) + 360) % 360;
            case "SQRT" -> Math.sqrt(a);
            case "ABS" -> Math.abs(a);
            case "ROUND" -> Math.signum(a) * Math.floor(Math.abs(a) + 0.5);
            case "FIX" -> Math.signum(a) * Math.floor(Math.abs(a));
            case "FUP" -> Math.signum(a) * Math.ceil(Math.abs(a));
            case "LN" -> a > 0 ? Math.log(a) : Double.NaN;
            default -> Math.exp(a);
        };
        if (Double.isNaN(r)) {
            throw new Fault(Code.E146_MACRO_NO_VALUE, at, excerpt(at, i));
        }
        return held(r, at);
    }

    /** After '#': the variable's number, written or computed ({@code #[#1 + 100]}). */
    long variable() throws Fault {
        int at = i;
        if (peek() == '[') {
            i++;
            Double v = expr();
            expect(']');
            return whole(v, at);
        }
        String d = digits();
        if (d.isEmpty()) {
            throw syntax(at);
        }
        return FlowWords.digits(d);
    }

    long whole(Double v, int at) throws Fault {
        if (v == null) {
            throw new Fault(Code.E146_MACRO_NO_VALUE, at, excerpt(at, i));
        }
        long r = Math.round(v);
        if (Math.abs(v - r) > 1e-6 || r < 0) {
            throw new Fault(Code.E013_INTEGER_EXPECTED, at, excerpt(at, i));
        }
        return r;
    }

    static double value(Double v) {
        return v == null ? 0 : v;
    }
}
