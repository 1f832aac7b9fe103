package gcnc.dmc;

/**
 * Which command a {@link Command} is, as a closed set: one constant per record, found once through
 * {@link Command.Visitor}. A question about commands that must be decided for every command (what a
 * resume restores, what a command is to its vector sequence, which variable it assigns) is a switch
 * expression over the kind with no default, so that a new command does not compile until each
 * such question has been answered for it.
 */
public enum CommandKind {
    LABEL, SERVO_HERE, VECTOR_MODE, VECTOR_ACCELERATION, VECTOR_DECELERATION, STOCK, FEED_MARK, SOURCE_MARK,
    REMARK, VECTOR_SPEED, VECTOR_POSITION, CIRCULAR_ARC, VECTOR_END, BEGIN_SEQUENCE, AWAIT_SEQUENCE,
    AFTER_VECTOR, OFFSET, WAIT, TOOL_NUMBER, REVOLVER, PASS_THROUGH_M, OUTPUT, GEAR_MASTER, SYNC_POINT,
    WAIT_PAST, GEAR_RATIO, PHASE_ERROR, INCREMENT_POSITION, DEFINE_POSITION, POSITION_ABSOLUTE, BEGIN,
    AFTER_MOTION, END, ANALOG_OUT, AXIS_SETTING, SOFT_LIMIT, JUMP, CALL, MESSAGE, STOP, ABORT, CLEAR_STACK,
    SET_VARIABLE, SET_DEADLINE;

    /** The kind of {@code c}. */
    public static CommandKind of(Command c) {
        return c.accept(KIND);
    }

    private static final Command.Visitor<CommandKind> KIND = new Command.Visitor<>() {
        public CommandKind label(Command.Label c) {
            return LABEL;
        }

        public CommandKind servoHere(Command.ServoHere c) {
            return SERVO_HERE;
        }

        public CommandKind vectorMode(Command.VectorMode c) {
            return VECTOR_MODE;
        }

        public CommandKind vectorAcceleration(Command.VectorAcceleration c) {
            return VECTOR_ACCELERATION;
        }

        public CommandKind vectorDeceleration(Command.VectorDeceleration c) {
            return VECTOR_DECELERATION;
        }

        public CommandKind stock(Command.Stock c) {
            return STOCK;
        }

        public CommandKind feedMark(Command.FeedMark c) {
            return FEED_MARK;
        }

        public CommandKind sourceMark(Command.SourceMark c) {
            return SOURCE_MARK;
        }

        public CommandKind remark(Command.Remark c) {
            return REMARK;
        }

        public CommandKind vectorSpeed(Command.VectorSpeed c) {
            return VECTOR_SPEED;
        }

        public CommandKind vectorPosition(Command.VectorPosition c) {
            return VECTOR_POSITION;
        }

        public CommandKind circularArc(Command.CircularArc c) {
            return CIRCULAR_ARC;
        }

        public CommandKind vectorEnd(Command.VectorEnd c) {
            return VECTOR_END;
        }

        public CommandKind beginSequence(Command.BeginSequence c) {
            return BEGIN_SEQUENCE;
        }

        public CommandKind awaitSequence(Command.AwaitSequence c) {
            return AWAIT_SEQUENCE;
        }

        public CommandKind afterVector(Command.AfterVector c) {
            return AFTER_VECTOR;
        }

        public CommandKind offset(Command.Offset c) {
            return OFFSET;
        }

        public CommandKind await(Command.Wait c) {
            return WAIT;
        }

        public CommandKind toolNumber(Command.ToolNumber c) {
            return TOOL_NUMBER;
        }

        public CommandKind revolver(Command.Revolver c) {
            return REVOLVER;
        }

        public CommandKind passThroughM(Command.PassThroughM c) {
            return PASS_THROUGH_M;
        }

        public CommandKind output(Command.Output c) {
            return OUTPUT;
        }

        public CommandKind gearMaster(Command.GearMaster c) {
            return GEAR_MASTER;
        }

        public CommandKind syncPoint(Command.SyncPoint c) {
            return SYNC_POINT;
        }

        public CommandKind waitPast(Command.WaitPast c) {
            return WAIT_PAST;
        }

        public CommandKind gearRatio(Command.GearRatio c) {
            return GEAR_RATIO;
        }

        public CommandKind phaseError(Command.PhaseError c) {
            return PHASE_ERROR;
        }

        public CommandKind incrementPosition(Command.IncrementPosition c) {
            return INCREMENT_POSITION;
        }

        public CommandKind definePosition(Command.DefinePosition c) {
            return DEFINE_POSITION;
        }

        public CommandKind positionAbsolute(Command.PositionAbsolute c) {
            return POSITION_ABSOLUTE;
        }

        public CommandKind begin(Command.Begin c) {
            return BEGIN;
        }

        public CommandKind afterMotion(Command.AfterMotion c) {
            return AFTER_MOTION;
        }

        public CommandKind end(Command.End c) {
            return END;
        }

        public CommandKind analogOut(Command.AnalogOut c) {
            return ANALOG_OUT;
        }

        public CommandKind axisSetting(Command.AxisSetting c) {
            return AXIS_SETTING;
        }

        public CommandKind softLimit(Command.SoftLimit c) {
            return SOFT_LIMIT;
        }

        public CommandKind jump(Command.Jump c) {
            return JUMP;
        }

        public CommandKind call(Command.Call c) {
            return CALL;
        }

        public CommandKind message(Command.Message c) {
            return MESSAGE;
        }

        public CommandKind stop(Command.Stop c) {
            return STOP;
        }

        public CommandKind abort(Command.Abort c) {
            return ABORT;
        }

        public CommandKind clearStack(Command.ClearStack c) {
            return CLEAR_STACK;
        }

        public CommandKind setVariable(Command.SetVariable c) {
            return SET_VARIABLE;
        }

        public CommandKind setDeadline(Command.SetDeadline c) {
            return SET_DEADLINE;
        }
    };
}
