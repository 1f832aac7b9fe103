package gcnc.dmc;

import gcnc.dmc.Command.*;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * Puts the commands of a downloaded program several to a line, joined by {@code ;}, up to the
 * model's characters per line (docs/galil.md, "Lines"): a Galil program is counted in lines (2,000
 * or 4,000), so packing is what lets a program of a few thousand blocks be downloaded whole (the
 * galil-controller.md survey: 14,972 lines of one command become 1,198 packed ones; gclib's
 * {@code GProgramDownload} packs the same way).
 *
 * <p>Where a line must break ({@link #PLACE}): a label begins one (a jump lands at a line's start);
 * a comment stands alone (Galil ignores the rest of a line after {@code NO}, and gcnc's marks are
 * read by people); a command after which the thread waits or leaves the line ends one ({@code AMS},
 * {@code AM}, {@code AV}, {@code WT}, {@code MF}/{@code MR}, {@code JP}, {@code JS}, {@code EN}), so
 * that the line thread 0 stands on ({@code _XQ0}) names the wait it stands in, as with one command
 * a line; a command whose text holds a {@code ;} stands alone. Nothing else decides: the same
 * commands always make the same lines, so the sender downloads the bytes the compile wrote.
 *
 * <p>Look-ahead: the commands of the line being filled, at most {@code width / 2}.
 */
public final class LinePacker implements Consumer<Instruction> {
    /** One line of the program: its commands, in order, and its text. */
    public record Line(List<Instruction> instructions, String text) {
    }

    /** How a command stands on a packed line. */
    enum Place {
        /** anywhere on a line */
        ANY,
        /** at the start of a line: a label */
        STARTS,
        /** last on its line: the thread waits or leaves the line here */
        ENDS,
        /** alone on its line: a comment */
        ALONE
    }

    private final int width;
    private final Consumer<Line> out;
    private final List<Instruction> line = new ArrayList<>();
    private final StringBuilder text = new StringBuilder(96);

    /**
     * @param width the most characters on a line (the model's {@code line_chars}); a command longer
     *              than it still goes on a line of its own (the controller limits' check reports it)
     */
    public LinePacker(int width, Consumer<Line> out) {
        this.width = width;
        this.out = out;
    }

    @Override
    public void accept(Instruction i) {
        String t = DmcPrinter.print(i.command());
        Place p = t.indexOf(';') >= 0 ? Place.ALONE : i.command().accept(PLACE);
        if (p == Place.STARTS || p == Place.ALONE || text.length() + 1 + t.length() > width) {
            flush();
        }
        if (!line.isEmpty()) {
            text.append(';');
        }
        line.add(i);
        text.append(t);
        if (p == Place.ENDS || p == Place.ALONE) {
            flush();
        }
    }

    /** Hands on the line being filled, if any: call once after the last command. */
    public void flush() {
        if (line.isEmpty()) {
            return;
        }
        out.accept(new Line(List.copyOf(line), text.toString()));
        line.clear();
        text.setLength(0);
    }

    /** {@code commands} packed: the lines a program of them downloads as. */
    public static List<Line> pack(List<Instruction> commands, int width) {
        List<Line> lines = new ArrayList<>();
        LinePacker p = new LinePacker(width, lines::add);
        commands.forEach(p);
        p.flush();
        return lines;
    }

    /** How many lines {@code commands} pack into. */
    public static int count(List<Instruction> commands, int width) {
        int[] n = {0};
        LinePacker p = new LinePacker(width, l -> n[0]++);
        commands.forEach(p);
        p.flush();
        return n[0];
    }

    private static final Visitor<Place> PLACE = new Visitor<>() {
        public Place label(Label c) {
            return Place.STARTS;
        }

        public Place servoHere(ServoHere c) {
            return Place.ANY;
        }

        public Place vectorMode(VectorMode c) {
            return Place.ANY;
        }

        public Place vectorAcceleration(VectorAcceleration c) {
            return Place.ANY;
        }

        public Place vectorDeceleration(VectorDeceleration c) {
            return Place.ANY;
        }

        public Place stock(Stock c) {
            return Place.ALONE;
        }

        public Place feedMark(FeedMark c) {
            return Place.ALONE;
        }

        public Place sourceMark(SourceMark c) {
            return Place.ALONE;
        }

        public Place remark(Remark c) {
            return Place.ALONE;
        }

        public Place vectorSpeed(VectorSpeed c) {
            return Place.ANY;
        }

        public Place vectorPosition(VectorPosition c) {
            return Place.ANY;
        }

        public Place circularArc(CircularArc c) {
            return Place.ANY;
        }

        public Place vectorEnd(VectorEnd c) {
            return Place.ANY;
        }

        public Place beginSequence(BeginSequence c) {
            return Place.ANY;
        }

        public Place awaitSequence(AwaitSequence c) {
            return Place.ENDS;
        }

        public Place afterVector(AfterVector c) {
            return Place.ENDS;
        }

        public Place offset(Offset c) {
            return Place.ANY;
        }

        public Place await(Wait c) {
            return Place.ENDS;
        }

        public Place toolNumber(ToolNumber c) {
            return Place.ANY;
        }

        public Place revolver(Revolver c) {
            return Place.ANY;
        }

        public Place passThroughM(PassThroughM c) {
            return Place.ANY;
        }

        public Place output(Output c) {
            return Place.ANY;
        }

        public Place gearMaster(GearMaster c) {
            return Place.ANY;
        }

        public Place syncPoint(SyncPoint c) {
            return Place.ANY;
        }

        public Place waitPast(WaitPast c) {
            return Place.ENDS;
        }

        public Place gearRatio(GearRatio c) {
            return Place.ANY;
        }

        public Place phaseError(PhaseError c) {
            return Place.ANY;
        }

        public Place incrementPosition(IncrementPosition c) {
            return Place.ANY;
        }

        public Place definePosition(DefinePosition c) {
            return Place.ANY;
        }

        public Place positionAbsolute(PositionAbsolute c) {
            return Place.ANY;
        }

        public Place begin(Begin c) {
            return Place.ANY;
        }

        public Place afterMotion(AfterMotion c) {
            return Place.ENDS;
        }

        public Place end(End c) {
            return Place.ENDS;
        }

        public Place analogOut(AnalogOut c) {
            return Place.ANY;
        }

        public Place axisSetting(AxisSetting c) {
            return Place.ANY;
        }

        public Place softLimit(SoftLimit c) {
            return Place.ANY;
        }

        public Place jump(Jump c) {
            return Place.ENDS;
        }

        public Place call(Call c) {
            return Place.ENDS;
        }

        public Place message(Message c) {
            return Place.ANY;
        }

        public Place stop(Stop c) {
            return Place.ANY;
        }

        public Place abort(Abort c) {
            return Place.ANY;
        }

        public Place clearStack(ClearStack c) {
            return Place.ANY;
        }

        public Place setVariable(SetVariable c) {
            return Place.ANY;
        }

        public Place setDeadline(SetDeadline c) {
            return Place.ANY;
        }
    };
}
