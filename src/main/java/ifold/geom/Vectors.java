package ifold.geom;

/**
 * Vectors of space as {@code double[3]}, the form the fold engine, the FOLD format and fold
 * scripts keep points and normals in: one copy of each operation for all of them. Each returns
 * a new array and leaves its arguments alone.
 */
public final class Vectors {
    private Vectors() {
    }

    public static double[] add(double[] a, double[] b) {
        return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    }

    public static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    public static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    public static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    /** {@code a} over its length (not finite where {@code a} is zero: callers divide only what has a length). */
    public static double[] unit(double[] a) {
        double length = Math.sqrt(dot(a, a));
        return new double[] {a[0] / length, a[1] / length, a[2] / length};
    }

    /** Rodrigues: vector {@code v} turned by {@code angle} (right-handed) about the unit axis {@code k}. */
    public static double[] turn(double[] v, double[] k, double angle) {
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        double[] kxv = cross(k, v);
        double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
        return new double[] {v[0] * c + kxv[0] * s + k[0] * kv * (1 - c), v[1] * c + kxv[1] * s + k[1] * kv * (1 - c),
            v[2] * c + kxv[2] * s + k[2] * kv * (1 - c)};
    }
}
