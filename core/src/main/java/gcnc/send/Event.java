package gcnc.send;

/**
 * What a run tells its front ends, in order: the command line's status line and the JSON event
 * stream ({@code gcnc run --format json}, one object per line, docs/run.md) are both made from
 * these, and the studio reads the same stream. Each record's components are the JSON object's
 * fields, in this order, after {@code "event"} (the record's name in kebab case).
 */
public sealed interface Event {
    /** Which event it is, for a switch over every one (Java 17 has no pattern switch): each record names its own. */
    Kind kind();

    enum Kind {
        CONNECTED, PREFLIGHT, WEAR, DOWNLOADED, STARTED, STATUS, BLOCK, STEP_WAIT, PROGRAM_STOP,
        PROGRAM_STOP_CONTINUED, HOLD, FINDING, MESSAGE, STOPPED, FINISHED
    }

    /** The link is open and the controller said what it is ({@code ^R^V}). */
    record Connected(String link, String controller) implements Event {
        public Kind kind() {
            return Kind.CONNECTED;
        }
    }

    /**
     * Pre-flight: what the controller has and what the program needs (never fewer than needed, or
     * the run stops here with E819); where the axes are in Galil counts ({@code position}) and as a
     * person reads it ({@code where}: program terms in the frame of the resume point's block, or of
     * the first motion's, then the counts in parentheses).
     */
    record Preflight(String model, int programLines, int programLinesNeeded, int labelsLeft, int labelsNeeded,
                     int variablesLeft, int variablesNeeded, int arraySpace, int vectorSlots, int vectorSlotsNeeded,
                     String pendingError, String limitSwitches, String motorsOff, double[] position, String where)
            implements Event {
        public Kind kind() {
            return Kind.PREFLIGHT;
        }
    }

    /**
     * Pre-flight: a wear offset the program's DMC was compiled with (one event per tool offset the
     * program uses that has a {@code wear.N}): where it was read, the offset, its X (as the program
     * writes X: a diameter when {@code diameter}) and Z wear in {@code unit} (mm or counts).
     */
    record Wear(String file, int offset, double x, double z, String unit, boolean diameter) implements Event {
        public Kind kind() {
            return Kind.WEAR;
        }
    }

    /** The program (or one step of it) is on the controller and was read back identical. */
    record Downloaded(int lines, boolean verified) implements Event {
        public Kind kind() {
            return Kind.DOWNLOADED;
        }
    }

    /** The program starts: {@code lines} DMC lines; {@code blocks}, the blocks the compile judged from where it starts (BlockTable#blocksFrom); {@code seconds} estimated. */
    record Started(String form, int lines, long blocks, double seconds, boolean dryRun, boolean step,
                   String resumeAt) implements Event {
        public Kind kind() {
            return Kind.STARTED;
        }
    }

    /**
     * Where the machine is: the DMC line executing (1-based, as the .dmc file numbers it) and the
     * G-code line (and N number, and file for a called program) it came from; the tool's position
     * in program coordinates (X as programmed, Z; null when unknown) and in Galil counts; feed and
     * spindle in force; progress 0..1 and the estimated seconds left; the override (VR) and
     * whether a feed hold is on.
     */
    record Status(int dmcLine, int line, String number, String file, double[] program, double[] counts,
                  double feed, boolean perRev, boolean inch, double rpm, String spindle, double progress,
                  double secondsLeft, double override, boolean held) implements Event {
        public Kind kind() {
            return Kind.STATUS;
        }
    }

    /** The executing G-code block changed: {@code completed} is the one before it (0: none yet). */
    record Block(int line, String number, int completed) implements Event {
        public Kind kind() {
            return Kind.BLOCK;
        }
    }

    /** Step mode waits for Enter before running {@code line}. */
    record StepWait(int line, String number) implements Event {
        public Kind kind() {
            return Kind.STEP_WAIT;
        }
    }

    /**
     * The program stopped at line {@code line} (M00, or M01 with the optional stop switch on) and
     * waits for the operator, the axes at rest: the block's comment ({@code (CHECK PART)}'s text,
     * "" for none). Enter ({@code gcnc run}), the studio's Start or the machine's cycle start button
     * goes on ({@link ProgramStopContinued}).
     */
    record ProgramStop(int line, String number, String comment) implements Event {
        public Kind kind() {
            return Kind.PROGRAM_STOP;
        }
    }

    /** The program stop at {@code line} ended: the program goes on with the next block ({@code by}: "operator" or "cycle-start"). */
    record ProgramStopContinued(int line, String by) implements Event {
        public Kind kind() {
            return Kind.PROGRAM_STOP_CONTINUED;
        }
    }

    /** Feed hold on ({@code held}) or off; the override in force. */
    record Hold(boolean held, double override) implements Event {
        public Kind kind() {
            return Kind.HOLD;
        }
    }

    /** A diagnostic of the run (a fault, a warning of the pre-flight), with its code and G-code line (0: none). */
    record Finding(String code, String severity, int line, String message) implements Event {
        public Kind kind() {
            return Kind.FINDING;
        }
    }

    /** A message the controller sent on its own (MG of a program, its error text), or a note of the sender. */
    record Message(String text) implements Event {
        public Kind kind() {
            return Kind.MESSAGE;
        }
    }

    /**
     * The run stopped before the end: why, the last block completed and the block executing (G-code
     * lines; 0 = none), where the axes are ({@code where}: program terms in the frame of the block
     * executing, then the Galil counts, as read after the stop or, when the link no longer answered,
     * at the last poll ({@code wherePolled}); null when they were never read), and the command that
     * resumes it (null when there is nothing to resume).
     */
    record Stopped(String reason, int completed, int executing, String where, boolean wherePolled, String resumeAt,
                   String resume) implements Event {
        public Kind kind() {
            return Kind.STOPPED;
        }
    }

    /** The program ran to its end (or the dry run did everything but motion). */
    record Finished(double seconds, boolean dryRun) implements Event {
        public Kind kind() {
            return Kind.FINISHED;
        }
    }
}
