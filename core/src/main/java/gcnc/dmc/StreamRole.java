package gcnc.dmc;

/**
 * Who carries out a command of the stream form (docs/galil.md, "The stream form"). The host can
 * only send what the controller takes from its command line; Galil's command reference marks the
 * trippoints ({@code AM}, {@code AV}, {@code WT}, {@code AD}, {@code MF} ...), labels, jumps and
 * calls as valid in a program only.
 */
public enum StreamRole {
    /** Sent as it is: the controller takes it from the command line. */
    SEND,
    /**
     * A wait the host carries out itself, by polling: {@code AMS} (until {@code _BGS} is 0),
     * {@code WT n} (n ms after the previous command was taken), {@code AV n} (until {@code _AVS}
     * reaches the sum of the sequence's AVs so far: AV is relative, _AVS from the sequence's start) and {@code JS #L} (the resident routine run with {@code XQ #L,0}, until {@code _XQ0}
     * is -1).
     */
    HOST,
    /**
     * Only valid inside a program, and too tight in time for a host to poll (the thread's
     * {@code AD}/{@code MF} on the spindle encoder): the block's commands go into a routine of the
     * resident program, called from the stream.
     */
    EMBED;

    /** The role of {@code c}. */
    public static StreamRole of(Command c) {
        return c.accept(ROLE);
    }

    private static final Command.Visitor<StreamRole> ROLE = new Command.Visitor<>() {
        public StreamRole label(Command.Label c) {
            return EMBED;
        }

        public StreamRole servoHere(Command.ServoHere c) {
            return SEND;
        }

        public StreamRole vectorMode(Command.VectorMode c) {
            return SEND;
        }

        public StreamRole vectorAcceleration(Command.VectorAcceleration c) {
            return SEND;
        }

        public StreamRole vectorDeceleration(Command.VectorDeceleration c) {
            return SEND;
        }

        public StreamRole stock(Command.Stock c) {
            return SEND;
        }

        public StreamRole feedMark(Command.FeedMark c) {
            return SEND;
        }

        public StreamRole sourceMark(Command.SourceMark c) {
            return SEND;
        }

        public StreamRole remark(Command.Remark c) {
            return SEND;
        }

        public StreamRole vectorSpeed(Command.VectorSpeed c) {
            return SEND;
        }

        public StreamRole vectorPosition(Command.VectorPosition c) {
            return SEND;
        }

        public StreamRole circularArc(Command.CircularArc c) {
            return SEND;
        }

        public StreamRole vectorEnd(Command.VectorEnd c) {
            return SEND;
        }

        public StreamRole beginSequence(Command.BeginSequence c) {
            return SEND;
        }

        public StreamRole awaitSequence(Command.AwaitSequence c) {
            return HOST;
        }

        public StreamRole afterVector(Command.AfterVector c) {
            return HOST;
        }

        public StreamRole offset(Command.Offset c) {
            return SEND;
        }

        public StreamRole await(Command.Wait c) {
            return HOST;
        }

        public StreamRole toolNumber(Command.ToolNumber c) {
            return SEND;
        }

        public StreamRole revolver(Command.Revolver c) {
            return EMBED; // the thesis's Delphi pseudo-command: no controller takes it
        }

        public StreamRole passThroughM(Command.PassThroughM c) {
            return EMBED; // likewise
        }

        public StreamRole output(Command.Output c) {
            return SEND;
        }

        public StreamRole gearMaster(Command.GearMaster c) {
            return SEND;
        }

        public StreamRole syncPoint(Command.SyncPoint c) {
            return SEND;
        }

        public StreamRole waitPast(Command.WaitPast c) {
            return EMBED;
        }

        public StreamRole gearRatio(Command.GearRatio c) {
            return SEND;
        }

        public StreamRole phaseError(Command.PhaseError c) {
            return SEND;
        }

        public StreamRole incrementPosition(Command.IncrementPosition c) {
            return SEND;
        }

        public StreamRole definePosition(Command.DefinePosition c) {
            return SEND;
        }

        public StreamRole positionAbsolute(Command.PositionAbsolute c) {
            return SEND;
        }

        public StreamRole begin(Command.Begin c) {
            return SEND;
        }

        public StreamRole afterMotion(Command.AfterMotion c) {
            return EMBED;
        }

        public StreamRole end(Command.End c) {
            return EMBED;
        }

        public StreamRole analogOut(Command.AnalogOut c) {
            return SEND;
        }

        public StreamRole axisSetting(Command.AxisSetting c) {
            return SEND;
        }

        public StreamRole softLimit(Command.SoftLimit c) {
            return SEND;
        }

        public StreamRole jump(Command.Jump c) {
            return EMBED;
        }

        public StreamRole call(Command.Call c) {
            return HOST;
        }

        public StreamRole message(Command.Message c) {
            return SEND;
        }

        public StreamRole stop(Command.Stop c) {
            return SEND;
        }

        public StreamRole abort(Command.Abort c) {
            return SEND;
        }

        public StreamRole clearStack(Command.ClearStack c) {
            return EMBED;
        }

        public StreamRole setVariable(Command.SetVariable c) {
            return SEND;
        }

        public StreamRole setDeadline(Command.SetDeadline c) {
            return SEND;
        }
    };
}
