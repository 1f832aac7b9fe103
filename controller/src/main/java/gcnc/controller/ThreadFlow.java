package gcnc.controller;

import java.util.List;

/**
 * The program threads' flow: XQ and HX from the host or a program, JP and JS, IF/ELSE/ENDIF, and the
 * loop that runs a thread's statements until it waits on a trippoint (AM, WT, AI) or its budget of
 * statements for this millisecond is spent.
 */
record ThreadFlow(VirtualGalil c, Statements statements) {

    private double eval(String e) throws GalilException {
        return Expressions.eval(e, c);
    }

    /** XQ [#label|line][,thread]. */
    String execute(String args) throws GalilException {
        List<String> a = Statements.split(args);
        int line = 0;
        if (!a.isEmpty() && !a.get(0).isEmpty()) {
            line = target(a.get(0));
        }
        int thread = a.size() > 1 ? (int) Statements.range(eval(a.get(1)), 0, 7) : 0;
        if (line >= c.program.size()) {
            throw new GalilException(Tc.UNDEFINED_LABEL);
        }
        c.threads[thread].start(line);
        return "";
    }

    /** A label ({@code #NAME}) or a line number, as XQ, JP and JS take them. */
    private int target(String t) throws GalilException {
        if (t.startsWith("#")) {
            int line = c.program.label(t.substring(1).strip());
            if (line < 0) {
                throw new GalilException(Tc.UNDEFINED_LABEL);
            }
            return line;
        }
        return (int) Statements.range(eval(t), 0, c.program.size() - 1);
    }

    String halt(String args) throws GalilException {
        if (args.isEmpty()) {
            for (ProgramThread t : c.threads) {
                t.halt();
            }
        } else {
            c.threads[(int) Statements.range(eval(args), 0, 7)].halt();
        }
        return "";
    }

    String jump(String cmd, String args, ProgramThread th) throws GalilException {
        Statements.onlyInProgram(th);
        List<String> a = Statements.split(args);
        int to = target(a.get(0));
        if (a.size() > 1 && eval(a.get(1)) == 0) {
            return "";
        }
        if (cmd.equals("JS")) {
            th.call(to);
        } else {
            th.jump(to);
        }
        return "";
    }

    /** IF (cond) / ELSE / ENDIF: a false IF, or an ELSE reached from its IF branch, skips to its match. */
    void flow(String st, ProgramThread th) throws GalilException {
        if (st.equals("ENDIF")) {
            return;
        }
        if (st.equals("ELSE")) {
            skip(th, false);
            return;
        }
        if (eval(st.substring(2).strip()) == 0) {
            skip(th, true);
        }
    }

    /** Moves the thread past the matching ENDIF (or, when {@code toElse}, past a matching ELSE first). */
    private void skip(ProgramThread th, boolean toElse) throws GalilException {
        int depth = 0;
        int line = th.line;
        int at = th.statement;
        while (line < c.program.size()) {
            List<String> sts = c.program.line(line).statements();
            for (; at < sts.size(); at++) {
                String s = sts.get(at);
                if (Statements.word(s, "IF")) {
                    depth++;
                } else if (s.equals("ENDIF") && depth-- == 0 || s.equals("ELSE") && depth == 0 && toElse) {
                    th.line = line;
                    th.statement = at + 1;
                    return;
                }
            }
            line++;
            at = 0;
        }
        throw new GalilException(Tc.IF_WITHOUT_ENDIF);
    }

    /** Runs up to {@code budget} statements of a thread, or until it waits on a trippoint that has not passed. */
    void run(ProgramThread th, int budget) {
        for (int n = 0; n < budget && th.running(); n++) {
            if (th.waitingFor != null) {
                if (!th.waitingFor.getAsBoolean()) {
                    return;
                }
                th.waitingFor = null;
            }
            if (th.line >= c.program.size()) {
                th.halt();
                return;
            }
            List<String> sts = c.program.line(th.line).statements();
            if (th.statement >= sts.size()) {
                th.line++;
                th.statement = 0;
                continue;
            }
            int line = th.line;
            String st = sts.get(th.statement++);
            try {
                statements.execute(st, th);
            } catch (GalilException e) {
                c.programError(th, line, st, e);
            }
        }
    }
}
