package ifold.job;

import ifold.geom.Triangle;
import ifold.mesh.PolygonSoup;
import ifold.wrap.Wrap;

/** The zig-zag demo's triangle wrapped as the demo wraps it, for the tests of what shows it. */
public final class ZigZagFixture {
    /** The triangle the tests use: A (0, 0), B (10, 0), C (3.5, 8). */
    public static final Triangle SHAPE = TriangleText.parse("0,0,10,0,3.5,8");

    private ZigZagFixture() {
    }

    /** {@link #SHAPE} wrapped alone, the strip starting at C and ending at A, entering from B's side. */
    public static Wrap.Result wrapped() throws Exception {
        PolygonSoup soup = new PolygonSoup();
        for (int i = 0; i < 3; i++) {
            soup.addVertex(SHAPE.corner(i).x(), SHAPE.corner(i).y(), SHAPE.corner(i).z());
        }
        soup.addTriangle(0, 1, 2);
        return Wrap.wrap(soup, new int[] {0, 1}, Wrap.Options.loneTriangle(SHAPE, new Wrap.Ends(2, 0, -1), Double.NaN, Double.NaN));
    }
}
