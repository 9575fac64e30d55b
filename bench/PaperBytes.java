import ifold.job.ModelFiles;
import ifold.job.WrapPath;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.refine.HamiltonianRefinement;
import ifold.wrap.Seam;
import ifold.wrap.Wrap;
import java.nio.file.Path;

/**
 * What the paper costs in memory: for each model, the heap the wrap's result holds (its
 * sheets, their faces, the journal of steps; measured after collections, the refinement loaded
 * before), over the faces of paper. The wrap at the default width, in this one JVM, along the
 * path a big model's one start follows ({@link Seam#ownInstead}: its own triangles, where they
 * make fewer faces), else the refinement; models of a few thousand faces or more (below that,
 * what class loading leaves behind is most of it).
 */
public final class PaperBytes {
    public static void main(String[] args) throws Exception {
        for (String name : args) {
            HalfedgeMesh mesh = ModelFiles.load(Path.of(name), MeshBuilder.Options.REPAIR_TRIANGULATE).built().mesh();
            Wrap.Options options = new Wrap.Options(Double.NaN, Double.NaN);
            HamiltonianRefinement.Result refinement = WrapPath.of(mesh).refinement();
            HamiltonianRefinement.Result own = Seam.ownInstead(refinement, options);
            HamiltonianRefinement.Result path = own != null ? own : refinement;
            long before = used();
            Wrap.Result result = Wrap.wrap(path, options);
            long after = used();
            long faces = 0;
            for (Wrap.Strip strip : result.strips()) {
                faces += strip.sheet().faceCount();
            }
            System.out.printf(java.util.Locale.ROOT, "%s (%s): %,d faces, the wrap holds %.1f MB, %.0f bytes a face (%,d steps)%n", name,
                    own != null ? "its own triangles" : "the refinement", faces, (after - before) / 1e6, (double) (after - before) / faces,
                    result.steps().size());
        }
    }

    private static long used() {
        for (int i = 0; i < 3; i++) {
            System.gc();
        }
        Runtime runtime = Runtime.getRuntime();
        return runtime.totalMemory() - runtime.freeMemory();
    }
}
