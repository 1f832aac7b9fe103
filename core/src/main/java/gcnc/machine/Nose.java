package gcnc.machine;

/**
 * The nose of the insert a tool offset stands for, as tool nose radius compensation (G41/G42)
 * uses it: the radius of the nose circle and the imaginary tip's direction from its centre.
 *
 * @param radius the nose radius, machine counts (the profile gives millimetres, or counts with
 *               {@code offsets.unit = counts}); 0 compensates by nothing
 * @param tip    the Fanuc/Haas tip direction 0-9 (docs/nose-compensation.md): 1-4 the corners, 5-8
 *               the axis directions, 0 and 9 the nose centre itself
 */
public record Nose(double radius, int tip) {
    public static final Nose NONE = new Nose(0, 0);

    public Nose {
        if (!(radius >= 0) || tip < 0 || tip > 9) {
            throw new IllegalArgumentException("nose radius " + radius + " tip " + tip);
        }
    }

    /**
     * The imaginary tip's offset from the nose centre in units of the radius, {x, z} in the machine
     * frame (x a radius, + away from the spindle centreline; z + toward the tailstock). Tip 3 (an
     * OD turning tool) is -x -z: the tool touches the diameter with its lowest point and the face
     * with its point nearest the chuck.
     */
    public double[] tipVector() {
        return switch (tip) {
            case 1 -> new double[] {1, 1};
            case 2 -> new double[] {1, -1};
            case 3 -> new double[] {-1, -1};
            case 4 -> new double[] {-1, 1};
            case 5 -> new double[] {0, 1};
            case 6 -> new double[] {1, 0};
            case 7 -> new double[] {0, -1};
            case 8 -> new double[] {-1, 0};
            default -> new double[] {0, 0};
        };
    }
}
