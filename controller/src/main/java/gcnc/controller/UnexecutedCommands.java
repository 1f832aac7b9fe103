package gcnc.controller;

import gcnc.dmc.Command;

/**
 * The commands of gcnc.dmc that {@link DmcCommands} does not execute: labels, marks and remarks, which do
 * nothing on a controller, and the commands this controller does not model as commands of gcnc.dmc, each
 * {@code ?} with TC 1 ({@link #notModelled}). Those are the thesis dialect's own words, which no Galil takes,
 * and the machine around the motion (gcnc.galil.MachineCode): program flow, messages, stops, the servo
 * settings, soft limits and assignments are the controller's own statements ({@link Statements},
 * {@link OwnCommands}, {@link Expressions}), which run them from the text before DmcCommands is asked
 * ({@link DmcCommands#handles} is false for their heads). Abstract, so that a new command of gcnc.dmc does
 * not compile until DmcCommands or this class handles it.
 */
abstract class UnexecutedCommands implements Command.Visitor<Void> {
    /** A command this controller does not model: {@code ?}, TC 1. */
    static Void notModelled() {
        throw Refused.refuse(Tc.UNRECOGNIZED);
    }

    @Override
    public Void label(Command.Label x) {
        return null;
    }

    @Override
    public Void stock(Command.Stock x) {
        return null;
    }

    @Override
    public Void feedMark(Command.FeedMark x) {
        return null;
    }

    @Override
    public Void sourceMark(Command.SourceMark x) {
        return null;
    }

    @Override
    public Void remark(Command.Remark x) {
        return null;
    }

    @Override
    public Void revolver(Command.Revolver x) {
        return notModelled(); // the thesis dialect's own words, not a Galil command
    }

    @Override
    public Void passThroughM(Command.PassThroughM x) {
        return notModelled();
    }

    /** Read as an assignment by {@link Statements} (its expression is evaluated there); not a command here. */
    @Override
    public Void phaseError(Command.PhaseError x) {
        return notModelled();
    }

    /** {@code DP} is the controller's own statement (OwnCommands.define); not reached here. */
    @Override
    public Void definePosition(Command.DefinePosition x) {
        return notModelled();
    }

    @Override
    public Void analogOut(Command.AnalogOut x) {
        return notModelled(); // AO addresses a Modbus device: none is attached to the virtual controller
    }

    @Override
    public Void axisSetting(Command.AxisSetting x) {
        return notModelled();
    }

    @Override
    public Void softLimit(Command.SoftLimit x) {
        return notModelled();
    }

    @Override
    public Void jump(Command.Jump x) {
        return notModelled();
    }

    @Override
    public Void call(Command.Call x) {
        return notModelled();
    }

    @Override
    public Void message(Command.Message x) {
        return notModelled();
    }

    @Override
    public Void stop(Command.Stop x) {
        return notModelled();
    }

    @Override
    public Void abort(Command.Abort x) {
        return notModelled();
    }

    @Override
    public Void clearStack(Command.ClearStack x) {
        return notModelled();
    }

    @Override
    public Void setVariable(Command.SetVariable x) {
        return notModelled();
    }

    @Override
    public Void setDeadline(Command.SetDeadline x) {
        return notModelled();
    }
}
