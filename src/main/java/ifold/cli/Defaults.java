package ifold.cli;

import ifold.geom.ParameterException;

/** Number options whose default the core chooses: left out, the core gets NaN, which stands for "the default". */
final class Defaults {
    private Defaults() {
    }

    /**
     * {@code value}, or NaN where the option was left out. Typed as NaN it is refused: NaN
     * stands for the default inside, and must not be one a user can type by accident.
     *
     * @throws ParameterException naming {@code parameter}, for a value typed as NaN
     */
    static double orDefault(Double value, String parameter) {
        if (value == null) {
            return Double.NaN;
        }
        if (value.isNaN()) {
            throw new ParameterException(parameter, "must be a number, got NaN");
        }
        return value;
    }
}
