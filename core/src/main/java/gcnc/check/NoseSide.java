package gcnc.check;

/**
 * Tool nose radius compensation in force (modal group 7): G40 off, G41 the nose on the left of
 * the programmed contour, G42 on its right, seen along the direction of travel with +Z to the
 * right and +X up (docs/nose-compensation.md).
 */
public enum NoseSide {
    OFF, LEFT, RIGHT;

    /** The G code a programmer writes for this side (its Fanuc A / Haas number). */
    String g() {
        return this == LEFT ? "G41" : this == RIGHT ? "G42" : "G40";
    }
}
