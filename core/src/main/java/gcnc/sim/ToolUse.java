package gcnc.sim;

import gcnc.machine.MachineModel;

/**
 * One station as the run used it, for a setup sheet's tool table: what the profile says it is,
 * the first and last G-code line that moved it, and how long it worked.
 *
 * @param station   the turret station (the T word's first digits; 0: moves before any tool)
 * @param kind      what the profile says the tool is ({@link MachineModel.ToolKind#TIP} when nothing)
 * @param insert    the profile's name for its outline ("C 12.7", "drill 10", "tip"); for a station
 *                  the profile does not describe, the default outline's name
 * @param described whether the profile describes the station (else it was checked as the default)
 * @param firstLine the G-code line of its first move
 * @param lastLine  the G-code line of its last move
 * @param seconds   its estimated share of the cycle: its moves and the dwells while it was selected
 */
public record ToolUse(int station, MachineModel.ToolKind kind, String insert, boolean described, int firstLine,
                      int lastLine, double seconds) {
}
