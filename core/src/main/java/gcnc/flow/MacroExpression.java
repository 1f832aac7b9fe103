package gcnc.flow;

import gcnc.diag.Code;

/**
 * Macro B expressions over a line ({@link MacroCursor}): {@code [ ]} and functions first, then
 * {@code * / MOD}, then {@code + -}; a value is a double, null when vacant (0 in arithmetic);
 * conditions {@code a EQ|NE|GT|GE|LT|LE b}. Variables are read from {@link Variables}: one the
 * machine alone knows is E147; a division by zero or a function outside its domain is E146.
 */
class MacroExpression extends MacroCursor {
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
                v = c == '+' ? value(v) + b : value(v) - b;
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
                v = value(v) * value(unary());
            } else if (c == '/') {
                i++;
                double b = value(unary());
                if (b == 0) {
                    throw new Fault(Code.E146_MACRO_NO_VALUE, start, s.substring(start, i).strip());
                }
                v = value(v) / b;
            } else if (keyword("MOD")) {
                double b = value(unary());
                if (b == 0) {
                    throw new Fault(Code.E146_MACRO_NO_VALUE, start, s.substring(start, i).strip());
                }
                v = value(v) % b;
            } else if (keywordAhead("AND")) {
                throw new Fault(Code.E111_MACRO_NOT_SUPPORTED_YET, i, excerpt(start));
            } else {
                return v;
            }
        }
    }

    Double unary() throws Fault {
        blank();
        if (peek() == '-') {
            i++;
            Double v = unary();
            return v == null ? null : -v;
        }
        if (peek() == '+') {
            i++;
            return unary();
        }
        return primary();
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
                return Double.valueOf(t);
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
        if (Double.isNaN(r) || Double.isInfinite(r)) {
            throw new Fault(Code.E146_MACRO_NO_VALUE, at, s.substring(at, i).strip());
        }
        return r + 0.0;
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
            throw new Fault(Code.E146_MACRO_NO_VALUE, at, s.substring(at, i).strip());
        }
        long r = Math.round(v);
        if (Math.abs(v - r) > 1e-6 || r < 0) {
            throw new Fault(Code.E013_INTEGER_EXPECTED, at, s.substring(at, i).strip());
        }
        return r;
    }

    static double value(Double v) {
        return v == null ? 0 : v;
    }
}
