package ifold.print;

import java.util.Locale;

/** The paper printed on: a standard size, upright or on its side, or one sheet as long as the strip. */
public enum Page {
    A4(210, 297), A4_LANDSCAPE(297, 210), LETTER(215.9, 279.4), LETTER_LANDSCAPE(279.4, 215.9), NONE(0, 0);

    private final double width;
    private final double height;

    Page(double width, double height) {
        this.width = width;
        this.height = height;
    }

    /** Its width in millimetres (0 for {@link #NONE}). */
    public double width() {
        return width;
    }

    /** Its height in millimetres (0 for {@link #NONE}). */
    public double height() {
        return height;
    }

    /** The names the options take: a4, a4-landscape, letter, letter-landscape, none. */
    public String optionName() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /**
     * The page named ({@link #optionName}, any case).
     *
     * @throws IllegalArgumentException naming the pages there are
     */
    public static Page of(String name) {
        for (Page page : values()) {
            if (page.optionName().equalsIgnoreCase(name.strip())) {
                return page;
            }
        }
        throw new IllegalArgumentException("expected a4, a4-landscape, letter, letter-landscape or none, got '" + name + "'");
    }
}
