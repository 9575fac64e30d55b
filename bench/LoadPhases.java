import ifold.job.ModelFiles;
import ifold.mesh.MeshBuilder;
import ifold.mesh.MeshValidator;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Topology;
import java.nio.file.Path;

/**
 * What `ifold info` does (read, build, validate, count the topology), RUNS times over in one
 * JVM: the first run is what a user's fresh process pays, the last ones the same work once the
 * JIT has compiled it. Prints one line a run: the phases in milliseconds.
 * Usage: java -cp 'build/install/ifold/lib/*' bench/LoadPhases.java MODEL [RUNS]
 */
public final class LoadPhases {
    public static void main(String[] args) throws Exception {
        Path model = Path.of(args[0]);
        int runs = args.length > 1 ? Integer.parseInt(args[1]) : 6;
        for (int run = 1; run <= runs; run++) {
            long t0 = System.nanoTime();
            PolygonSoup soup = ModelFiles.read(model);
            long t1 = System.nanoTime();
            MeshBuilder.Result built = ModelFiles.build(model, soup, MeshBuilder.Options.REPAIR);
            long t2 = System.nanoTime();
            boolean valid = MeshValidator.validate(built.mesh()).isEmpty();
            long t3 = System.nanoTime();
            int genus = Topology.of(built.mesh()).genus();
            long t4 = System.nanoTime();
            System.out.printf("run %d: read %.0f build %.0f validate %.0f topology %.0f total %.0f ms (valid %b, genus %d)%n", run,
                    (t1 - t0) / 1e6, (t2 - t1) / 1e6, (t3 - t2) / 1e6, (t4 - t3) / 1e6, (t4 - t0) / 1e6, valid, genus);
        }
    }
}
