import ifold.check.LayerOrder;
import ifold.check.PaperCollisions;
import ifold.foldfile.FoldFile;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.io.MeshReaders;
import ifold.refine.FacePreparation;
import ifold.refine.HamiltonianRefinement;
import ifold.wrap.Wrap;
import ifold.wrap.WrapAnalysis;
import ifold.wrap.WrapExport;
import ifold.wrap.PaperInSpace;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The README's table of layers: each model wrapped at the default width on its own triangles
 * and on its prepared ones, with the most layers, the tucks and the collision checker's counts
 * on the exported OBJ. A model given as "box:A" is the box A × 1 × 1.
 */
public final class Layers {
    public static void main(String[] args) throws Exception {
        System.out.println("model | triangles (prepared) | on its own triangles | on the prepared ones");
        for (String name : args) {
            PolygonSoup soup = name.startsWith("box:") ? Solids.box(Double.parseDouble(name.substring(4)), 1, 1) : MeshReaders.read(Path.of(name));
            HalfedgeMesh mesh = MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
            FacePreparation.Result prepared = FacePreparation.prepare(mesh);
            StringBuilder line = new StringBuilder(name + " | " + mesh.faceCount()
                    + (prepared.prepared() > 0 ? " (" + prepared.trianglesAfter() + ")" : ""));
            line.append(" | ").append(wrap(mesh, mesh));
            line.append(" | ").append(prepared.prepared() > 0 ? wrap(prepared.mesh(), mesh) : "the same");
            System.out.println(line);
        }
    }

    private static String wrap(HalfedgeMesh triangles, HalfedgeMesh model) throws Exception {
        long start = System.nanoTime();
        Wrap.Result result;
        try {
            result = Wrap.wrap(HamiltonianRefinement.refine(triangles), new Wrap.Options(Double.NaN, Double.NaN));
        } catch (Wrap.WrapException e) {
            return "refused: " + e.getMessage().substring(0, Math.min(60, e.getMessage().length())) + "...";
        }
        double seconds = (System.nanoTime() - start) * 1e-9;
        List<PaperInSpace> geometries = new ArrayList<>();
        for (Wrap.Strip strip : result.strips()) {
            geometries.add(PaperInSpace.of(strip.sheet(), result.frames()));
        }
        WrapAnalysis analysis = WrapAnalysis.of(result, geometries);
        Path obj = Files.createTempFile("layers", ".obj");
        try {
            WrapExport.writeObj(obj, "bench/Layers", result, geometries);
            double[] surface = new double[9 * model.faceCount()];
            for (int f = 0; f < model.faceCount(); f++) {
                for (int k = 0; k < 3; k++) {
                    for (int axis = 0; axis < 3; axis++) {
                        surface[9 * f + 3 * k + axis] = model.coordinate(model.faceVertex(f, k), axis);
                    }
                }
            }
            PaperCollisions.Result collisions = PaperCollisions.check(Files.readString(obj), result.thickness(), surface);
            List<FoldFile.Folded> sheets = new ArrayList<>();
            for (Wrap.Strip strip : result.strips()) {
                sheets.add(new FoldFile.Folded(strip.sheet(), result.frames()));
            }
            LayerOrder.Result order = LayerOrder.check(FoldFile.text("bench/Layers", sheets));
            return String.format(java.util.Locale.ROOT, "%d layers, %d tucks, %.1f s; %s; %s", analysis.maxLayers(),
                    result.count(Wrap.Kind.TUCK), seconds, order.valid() ? "layer order valid" : order.summary(), collisions.summary());
        } finally {
            Files.deleteIfExists(obj);
        }
    }
}
