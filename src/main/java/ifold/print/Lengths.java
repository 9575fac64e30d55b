package ifold.print;

import java.util.Locale;

/** Lengths on paper as people write them: 2cm, 20mm, 0.8in, 20 mm; or auto, for the printer to choose. */
public final class Lengths {
    private Lengths() {
    }

    /** What {@link #millimetres} reads as "choose for me". */
    public static final String AUTOMATIC = "auto";

    /**
     * The length in millimetres, or NaN for {@link #AUTOMATIC}.
     *
     * @throws IllegalArgumentException where it is not a positive number with a unit mm, cm or in
     */
    public static double millimetres(String text) {
        String t = text.strip().toLowerCase(Locale.ROOT).replace(" ", "");
        if (t.equals(AUTOMATIC)) {
            return Double.NaN;
        }
        double factor;
        String number;
        if (t.endsWith("mm")) {
            factor = 1;
            number = t.substring(0, t.length() - 2);
        } else if (t.endsWith("cm")) {
            factor = 10;
            number = t.substring(0, t.length() - 2);
        } else if (t.endsWith("m")) {
            factor = 1000;
            number = t.substring(0, t.length() - 1);
        } else if (t.endsWith("in")) {
            factor = 25.4;
            number = t.substring(0, t.length() - 2);
        } else {
            throw new IllegalArgumentException("expected auto or a length with its unit, such as 2cm, 20mm or 0.8in, got '" + text + "'");
        }
        double value;
        try {
            value = Double.parseDouble(number);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("expected auto or a length with its unit, such as 2cm, 20mm or 0.8in, got '" + text + "'");
        }
        double mm = value * factor;
        if (!(mm >= 2) || !(mm <= 1000)) {
            throw new IllegalArgumentException("must be from 2 mm to 1 m, got '" + text + "'");
        }
        return mm;
    }
}
