package ifold.scene;

/** Reveals the triangles of a geometry one after another, in mesh order. */
public final class RevealAnimation implements Animation {
    private final Geometry geometry;
    private final int total;

    public RevealAnimation(Geometry geometry) {
        this.geometry = geometry;
        this.total = geometry.mesh().triangleCount();
    }

    public Geometry geometry() {
        return geometry;
    }

    /** How many triangles are revealed at {@code position}. */
    public static int revealedAt(double position) {
        return (int) Math.floor(position);
    }

    @Override
    public int stepCount() {
        return total;
    }

    @Override
    public void apply(double position) {
        geometry.setRevealed(revealedAt(position));
    }

    @Override
    public String describe(double position) {
        return "path: triangle " + revealedAt(position) + " of " + total;
    }
}
