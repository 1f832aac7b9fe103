package gcnc.cli;

import gcnc.diag.Code;
import gcnc.tables.ErrorMessages;
import gcnc.tables.GFunction;
import gcnc.tables.MFunction;
import gcnc.tables.TableException;
import gcnc.tables.Tables;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

@Command(name = "tables", mixinStandardHelpOptions = true,
        description = "Print the preparatory (G) and miscellaneous (M) functions and every diagnostic code.")
final class TablesCommand implements Callable<Integer> {
    @Mixin
    CommonOptions common;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        Tables t;
        try {
            t = common.loadTables();
        } catch (TableException e) {
            return Reporter.tableFault(spec.commandLine().getErr(), e, common.language());
        }
        boolean es = common.language() == ErrorMessages.Lang.ES;
        out.println(es ? "Funciones preparatorias (tabla 3)" : "Preparatory functions (thesis Table 3)");
        out.println(es ? "Código  Grupo  Descripción" : "Code  Group  Description");
        for (GFunction g : t.allG()) {
            out.printf("%-5s  %5s  %s%n", g.name(), g.modal() ? String.format("%02d", g.group()) : "-", es ? g.spanish() : g.english());
        }
        out.println();
        out.println(es ? "Funciones misceláneas (tabla 4)" : "Miscellaneous functions (thesis Table 4)");
        out.println(es ? "Código  Grupo  Momento  Descripción" : "Code  Group  Applied  Description");
        for (MFunction m : t.allM()) {
            String when = m.moment() == 1 ? "start" : m.moment() == 0 ? "during" : "end";
            out.printf("%-5s  %5s  %-7s  %s%n", m.name(), String.format("%02d", m.group()), when, es ? m.spanish() : m.english());
        }
        out.println();
        out.println(es ? "Diagnósticos (tabla 5 y códigos de gcnc)" : "Diagnostics (thesis Table 5 and gcnc's own codes)");
        for (Code c : Code.values()) {
            out.printf("%s  %s%n", c.id(), t.messages().template(c, common.language()));
        }
        out.flush();
        return ExitCode.CLEAN;
    }
}
