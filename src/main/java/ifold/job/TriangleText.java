package ifold.job;

import ifold.geom.Tolerance;
import ifold.geom.Triangle;
import ifold.geom.ParameterException;
import java.util.Locale;
import org.joml.Vector3d;

/** The zig-zag demo's triangle, read from the text the user typed. */
public final class TriangleText {
    private TriangleText() {
    }

    /**
     * Parses {@code x1,y1,x2,y2,x3,y3} (a triangle in the plane z = 0) or
     * {@code x1,y1,z1,x2,y2,z2,x3,y3,z3} (one in space).
     *
     * @throws ParameterException naming {@code triangle}: a value that is not a finite number, a
     *     triangle with no area, or one too small for its distance from the origin or beyond
     *     the sizes a double can square
     */
    public static Triangle parse(String text) {
        String[] parts = text.split(",", -1);
        if (parts.length != 6 && parts.length != 9) {
            throw new ParameterException("triangle", "expected six numbers x1,y1,x2,y2,x3,y3 or nine x1,y1,z1,...,z3, got '" + text + "'");
        }
        double[] values = new double[parts.length];
        for (int i = 0; i < parts.length; i++) {
            try {
                values[i] = Double.parseDouble(parts[i].strip());
            } catch (NumberFormatException e) {
                throw new ParameterException("triangle", "'" + parts[i].strip() + "' is not a number");
            }
            if (!Double.isFinite(values[i])) {
                throw new ParameterException("triangle", "'" + parts[i].strip() + "' is not a finite number");
            }
        }
        Triangle triangle;
        try {
            triangle = values.length == 6 ? Triangle.planar(values[0], values[1], values[2], values[3], values[4], values[5])
                    : new Triangle(new Vector3d(values[0], values[1], values[2]), new Vector3d(values[3], values[4], values[5]),
                            new Vector3d(values[6], values[7], values[8]));
        } catch (IllegalArgumentException e) {
            throw new ParameterException("triangle", e.getMessage());
        }
        double size = Math.max(triangle.opposite(0), Math.max(triangle.opposite(1), triangle.opposite(2)));
        double far = 0;
        for (double value : values) {
            far = Math.max(far, Math.abs(value));
        }
        if (far > 1e6 * size) {
            // Thickness offsets of a millionth of the size would drown in the coordinates' rounding.
            throw new ParameterException("triangle", "the triangle is too small for its distance from the origin: move it nearer");
        }
        if (far > Tolerance.LARGEST_SIZE || size < Tolerance.SMALLEST_SIZE) {
            // Fourth powers of lengths (a frame's cross products squared) would overflow or underflow a double.
            throw new ParameterException("triangle", String.format(Locale.ROOT, "iFold wraps triangles of sizes from %.0e to %.0e,"
                    + " got %s up to %.3g", Tolerance.SMALLEST_SIZE, Tolerance.LARGEST_SIZE,
                    far > Tolerance.LARGEST_SIZE ? "coordinates" : "sides", far > Tolerance.LARGEST_SIZE ? far : size));
        }
        return triangle;
    }
}
