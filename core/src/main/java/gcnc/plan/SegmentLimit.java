package gcnc.plan;

import gcnc.machine.GalilModel;
import gcnc.machine.MachineProfile;

/**
 * The longest straight segment the controller takes in one {@code VP} (tables/galil_models.csv
 * {@code segment_max}: COMALL VP, "the length of each vector segment must be limited to 8,388,607"),
 * and how many equal pieces a longer straight move is written as, one after the other in the same
 * sequence (galil-controller.md §6.1: "split the line"). Each piece is planned a few counts shorter
 * than the limit, since the emitter rounds the points between them to whole counts.
 */
public record SegmentLimit(double max) {
    /** The counts the emitter's rounding may add to a piece (both ends half a count on each axis, and a margin). */
    static final double ROUNDING = 4;

    /** The limit of the profile's Galil model. */
    public static SegmentLimit of(MachineProfile profile) {
        return new SegmentLimit(profile.controllerLimits().model().range(GalilModel.Limit.SEGMENT_LENGTH).max());
    }

    /** How many pieces a straight move of {@code length} counts is written as: 1 when it fits. */
    public int parts(double length) {
        return length <= max - ROUNDING ? 1 : (int) Math.ceil(length / (max - ROUNDING));
    }
}
