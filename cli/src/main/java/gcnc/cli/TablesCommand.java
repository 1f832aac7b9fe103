package gcnc.cli;

import gcnc.diag.Code;
import gcnc.tables.ErrorMessages;
import gcnc.machine.Control;
import gcnc.machine.GFunction;
import gcnc.machine.MFunction;
import gcnc.tables.TableException;
import gcnc.tables.Tables;
import java.io.PrintWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;

@Command(name = "tables", mixinStandardHelpOptions = true,
        description = "Print the preparatory (G) and miscellaneous (M) functions of the machine's control"
                + " (--machine, --control) and every diagnostic code.")
final class TablesCommand extends StreamsCommand {
    @Mixin
    CommonOptions common;

    @Override
    Integer call(PrintWriter out, PrintWriter err) {
        Tables t;
        Control c;
        try {
            t = common.loadTables();
            c = common.loadProfile(t).control();
        } catch (TableException e) {
            return Reporter.tableFault(spec.commandLine().getErr(), e, common.language());
        }
        boolean es = common.language() == ErrorMessages.Lang.ES;
        out.println((es ? "Control " : "Control ") + c.name() + ": " + c.description());
        out.println();
        out.println(es ? "Funciones preparatorias (tabla 3)" : "Preparatory functions (thesis Table 3)");
        out.println(es ? "Código  Grupo  Función               Descripción" : "Code  Group  Function              Description");
        for (GFunction g : c.allG()) {
            out.printf("%-5s  %5s  %-20s  %s%n", g.name(), g.modal() ? String.format("%02d", g.group()) : "-",
                    g.role().name().toLowerCase(java.util.Locale.ROOT), es ? g.spanish() : g.english());
        }
        out.println();
        out.println(es ? "Funciones misceláneas (tabla 4)" : "Miscellaneous functions (thesis Table 4)");
        out.println(es ? "Código  Grupo  Momento  Función         Descripción" : "Code  Group  Applied  Function        Description");
        for (MFunction m : c.allM()) {
            String when = m.moment() == 1 ? "start" : m.moment() == 0 ? "during" : "end";
            out.printf("%-5s  %5s  %-7s  %-14s  %s%n", m.name(), String.format("%02d", m.group()), when,
                    m.role().name().toLowerCase(java.util.Locale.ROOT), es ? m.spanish() : m.english());
        }
        if (c.builderM()) {
            out.println(es ? "Otros códigos M: del fabricante de la máquina (salidas del perfil)"
                    : "Other M codes: machine-builder functions (the profile's outputs)");
        }
        out.println();
        out.println(es ? "Diagnósticos (tabla 5 y códigos de gcnc)" : "Diagnostics (thesis Table 5 and gcnc's own codes)");
        for (Code code : Code.values()) {
            out.printf("%s  %s%n", code.id(), t.messages().template(code, common.language()));
        }
        out.flush();
        return ExitCode.CLEAN;
    }
}
