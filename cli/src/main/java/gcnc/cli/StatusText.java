package gcnc.cli;

import gcnc.send.Event;
import gcnc.send.EventSink;
import java.io.PrintWriter;
import java.util.Locale;

/**
 * {@code gcnc run}'s screen, like the thesis's MEMORY mode: a status line that the next one
 * overwrites on a terminal (one line per block elsewhere, as a log), messages on their own lines,
 * findings GCC-style on standard error ({@code part.nc:37:1: error[E820]: ...}).
 * <pre>
 * N120 line 37  X24.500 Z-3.200  F0.20/rev  S1200 cw  41%  0:00:19 left
 * </pre>
 */
final class StatusText implements EventSink {
    private final PrintWriter out;
    private final PrintWriter err;
    private final String file;
    private final boolean quiet;
    private final boolean terminal;
    private final Phrases say;
    private boolean blockChanged;
    private boolean lineOpen;

    StatusText(PrintWriter out, PrintWriter err, String file, boolean quiet, boolean terminal, Phrases say) {
        this.say = say;
        this.out = out;
        this.err = err;
        this.file = file;
        this.quiet = quiet;
        this.terminal = terminal;
    }

    @Override
    public synchronized void accept(Event e) {
        String text = switch (e.kind()) {
            case FINDING -> {
                Event.Finding f = (Event.Finding) e;
                endLine();
                err.println(file + (f.line() > 0 ? ":" + f.line() + ":1" : "") + ": " + f.severity() + "[" + f.code()
                        + "]: " + f.message());
                err.flush();
                yield null;
            }
            case STATUS -> {
                status((Event.Status) e);
                yield null;
            }
            case BLOCK -> {
                blockChanged = true;
                yield null;
            }
            case STOPPED -> {
                stopped((Event.Stopped) e);
                yield null;
            }
            case CONNECTED -> {
                Event.Connected c = (Event.Connected) e;
                yield say.get("run.connected", c.link(), c.controller());
            }
            case PREFLIGHT -> {
                Event.Preflight p = (Event.Preflight) e;
                yield say.get("run.preflight", p.model(), p.programLinesNeeded(), p.programLines(), p.labelsNeeded(),
                        p.labelsLeft(), p.variablesNeeded(),
                        p.variablesLeft() < 0 ? "?" : Integer.toString(p.variablesLeft()), p.vectorSlots(),
                        p.vectorSlotsNeeded(), p.limitSwitches().isEmpty() ? say.get("run.clear") : p.limitSwitches(),
                        p.where());
            }
            case WEAR -> {
                Event.Wear w = (Event.Wear) e;
                yield say.get("run.wear", w.file(),
                        gcnc.machine.ToolWear.describe(w.offset(), w.x(), w.z(), w.diameter(), w.unit()));
            }
            case DOWNLOADED -> {
                Event.Downloaded d = (Event.Downloaded) e;
                yield say.get("run.downloaded", d.lines());
            }
            case STARTED -> {
                Event.Started s = (Event.Started) e;
                yield say.get(s.dryRun() ? "run.started_dry" : "run.started", file,
                        s.resumeAt() != null ? say.get("run.from_line", s.resumeAt()) : "", s.blocks(), s.lines(),
                        clock(s.seconds()), say.get(s.step() ? "run.keys_step" : "run.keys"));
            }
            case STEP_WAIT -> {
                Event.StepWait w = (Event.StepWait) e;
                yield say.get("run.step_wait", w.line(), w.number() != null ? " (N" + w.number() + ")" : "");
            }
            case PROGRAM_STOP -> {
                Event.ProgramStop p = (Event.ProgramStop) e;
                yield say.get("run.program_stop", p.line(), p.number() != null ? " (N" + p.number() + ")" : "",
                        p.comment().isEmpty() ? "" : ": " + p.comment());
            }
            case PROGRAM_STOP_CONTINUED -> {
                Event.ProgramStopContinued p = (Event.ProgramStopContinued) e;
                yield say.get(p.by().equals("operator") ? "run.program_stop_continued" : "run.program_stop_cycle_start",
                        p.line());
            }
            case HOLD -> {
                Event.Hold h = (Event.Hold) e;
                yield h.held() ? say.get("run.hold") : say.get("run.feed", Math.round(h.override() * 100),
                        String.format(Locale.ROOT, "%.2f", h.override()));
            }
            case MESSAGE -> {
                Event.Message m = (Event.Message) e;
                yield say.get("run.message", m.text());
            }
            case FINISHED -> {
                Event.Finished f = (Event.Finished) e;
                yield f.dryRun() ? say.get("run.finished_dry") : say.get("run.finished", clock(f.seconds()));
            }
        };
        if (text != null && !quiet) {
            say(text);
        }
    }

    private void status(Event.Status s) {
        if (quiet) {
            return;
        }
        if (terminal) {
            out.print("\r" + line(s) + "\u001b[K");
            out.flush();
            lineOpen = true;
        } else if (blockChanged) {
            out.println(line(s));
            out.flush();
        }
        blockChanged = false;
    }

    private void stopped(Event.Stopped s) {
        endLine();
        // a dropped link did not stop the controller: it may run on without the host (E851)
        boolean dropped = "E851".equals(s.reason());
        out.println(say.get(dropped ? "run.link_dropped" : "run.stopped", block(s.completed()),
                block(s.executing())));
        if (s.where() != null) {
            out.println(say.get(s.wherePolled() ? "run.axes_last_seen" : "run.axes_at", s.where()));
        }
        if (s.resume() != null) {
            out.println(say.get("run.resume", s.resume()));
        }
        out.flush();
    }

    private String block(int line) {
        return line == 0 ? say.get("run.none") : say.get("run.line", line);
    }

    private void say(String text) {
        if (text == null) {
            return;
        }
        endLine();
        out.println(text);
        out.flush();
    }

    private void endLine() {
        if (lineOpen) {
            out.println();
            lineOpen = false;
        }
    }

    /** The status line: block, position in program coordinates, feed, spindle, progress, time left. */
    String line(Event.Status s) {
        StringBuilder b = new StringBuilder();
        if (s.number() != null) {
            b.append('N').append(s.number()).append(' ');
        }
        b.append(say.get("run.line", s.line()));
        // program terms first (X as the program writes it, Z from work zero, the program's units), the
        // counts after them, as every position gcnc run prints (send/PositionText)
        String counts = s.counts() == null ? null : Math.round(s.counts()[0]) + "," + Math.round(s.counts()[1]);
        if (s.program() != null) {
            String f = s.inch() ? "%.4f" : "%.3f";
            b.append(String.format(Locale.ROOT, "  X" + f + " Z" + f, s.program()[0], s.program()[1]));
            if (counts != null) {
                b.append(" (Galil counts ").append(counts).append(')');
            }
        } else if (counts != null) {
            b.append("  ").append(counts).append(" (Galil counts)");
        }
        if (!Double.isNaN(s.feed())) {
            b.append(String.format(Locale.ROOT, "  F%s%s", trim(s.feed()), s.perRev() ? "/rev" : "/min"));
        }
        if (!Double.isNaN(s.rpm()) && s.spindle() != null) {
            b.append("  S").append(Math.round(s.rpm())).append(' ').append(s.spindle());
        }
        b.append(String.format(Locale.ROOT, "  %d%%  %s %s", Math.round(s.progress() * 100), clock(s.secondsLeft()),
                say.get("run.left")));
        if (s.held()) {
            b.append("  HOLD");
        } else if (s.override() != 1) {
            b.append(String.format(Locale.ROOT, "  feed %d%%", Math.round(s.override() * 100)));
        }
        return b.toString();
    }

    private static String trim(double v) {
        String t = String.format(Locale.ROOT, "%.4f", v).replaceAll("0+$", "");
        return t.endsWith(".") ? t + "0" : t;
    }

    static String clock(double seconds) {
        long s = Math.round(seconds);
        return String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60);
    }
}
