package ifold.ui.model;

/**
 * Why a job cannot run: a parameter out of range (its {@code field} is the core's name of
 * the parameter: width, thickness, start, end, enterFrom, angle, overhang, triangle, maxFaces,
 * model, script; a new model's around, across, subdivisions; an output's file), or a failure of the job itself (no field). One line, never a stack trace.
 */
public record Problem(String field, String message) {
    /** A failure that is no field's fault: a file that cannot be read, a model that cannot be wrapped. */
    public static Problem of(String message) {
        return new Problem(null, message);
    }
}
