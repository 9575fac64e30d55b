import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.job.WrapPath;
import ifold.wrap.LayerFloor;
import ifold.wrap.Seam;
import ifold.wrap.Wrap;

/**
 * Tucks and layers against the sharpness of a corner (docs/wrap.md): a tetrahedron on a unit
 * equilateral base whose three side faces have an apex angle of A degrees, wrapped at the
 * default width as ifold wrap does (prepared, refined, and begun where its layers are fewest).
 */
public final class Corners {
    public static void main(String[] args) throws Exception {
        System.out.println("| apex angle | tucks | most tucks on a path triangle | layers at most | floor for any strip | faces | seconds |");
        System.out.println("|---|---|---|---|---|---|---|");
        for (String arg : args) {
            double degrees = Double.parseDouble(arg);
            HalfedgeMesh spike = MeshBuilder.build(spike(degrees), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
            long start = System.nanoTime();
            String row;
            try {
                Seam.Chosen chosen = Seam.wrap(WrapPath.of(spike).refinement(), new Wrap.Options(Double.NaN, Double.NaN),
                        Wrap.Watcher.NONE);
                Wrap.Result result = chosen.result();
                int[] tucks = new int[result.mesh().faceCount()];
                for (Wrap.Step step : result.steps()) {
                    if (step.kind() == Wrap.Kind.TUCK) {
                        tucks[step.triangle()]++;
                    }
                }
                int most = 0;
                for (int t : tucks) {
                    most = Math.max(most, t);
                }
                row = String.format(java.util.Locale.ROOT, "| %s° | %d | %d | %d | %d | %d | %.1f |", arg, result.count(Wrap.Kind.TUCK), most,
                        chosen.placed().analysis().maxLayers(), LayerFloor.of(spike).layers(),
                        result.strips().get(0).sheet().faceCount(),
                        (System.nanoTime() - start) * 1e-9);
            } catch (Wrap.WrapException e) {
                row = String.format(java.util.Locale.ROOT, "| %s° | refused after %.1f s: %s |", arg, (System.nanoTime() - start) * 1e-9,
                        e.getMessage().replaceAll(".*(the excess is not hidden after \\d+ tucks).*", "$1"));
            }
            System.out.println(row);
        }
    }

    /** Apex straight above the centre of a unit equilateral base, so high that each side face's apex angle is the one asked. */
    static PolygonSoup spike(double degrees) {
        double inradius = 1 / (2 * Math.sqrt(3));
        double slant = 0.5 / Math.tan(Math.toRadians(degrees) / 2); // apex to the middle of a base edge
        double height = slant > inradius ? Math.sqrt(slant * slant - inradius * inradius) : 0.05;
        double circumradius = 1 / Math.sqrt(3);
        PolygonSoup soup = new PolygonSoup();
        for (int k = 0; k < 3; k++) {
            soup.addVertex(circumradius * Math.cos(2 * Math.PI * k / 3), circumradius * Math.sin(2 * Math.PI * k / 3), 0);
        }
        soup.addVertex(0, 0, height);
        soup.addTriangle(0, 2, 1);
        soup.addTriangle(0, 1, 3);
        soup.addTriangle(1, 2, 3);
        soup.addTriangle(2, 0, 3);
        return soup;
    }
}
