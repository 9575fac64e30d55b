import ifold.check.LayerOrder;
import ifold.check.PaperCollisions;
import ifold.job.Collisions;
import ifold.wrap.PaperInSpace;
import ifold.foldfile.FoldFile;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.refine.HamiltonianRefinement;
import ifold.wrap.Wrap;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Wraps random solids of three kinds at the default width and checks each layer order from its
 * FOLD file (ifold.check.LayerOrder): star-shaped icosahedra whose corners move in and out,
 * boxes of random sides turned at random (their faces quads the builder cuts), octahedra
 * stretched along the axes. Prints each solid whose order is broken or that is refused, then
 * the count; and the paper's collisions (ifold.check.PaperCollisions on the OBJ's text): each
 * solid whose paper crosses itself or the model, and how many of each kind do. Seeds 1 to N; the kind k of seed s draws from SplittableRandom(31 s + k), as
 * WrapTest's wrapsTurnedBoxes does for boxes.
 */
public final class RandomSolids {
    private static final String[] KINDS = {"star", "turned box", "stretched octahedron"};

    public static void main(String[] args) throws Exception {
        int n = args.length > 0 ? Integer.parseInt(args[0]) : 40;
        int broken = 0;
        int refused = 0;
        int[] colliding = new int[KINDS.length];
        for (int seed = 1; seed <= n; seed++) {
            for (int kind = 0; kind < KINDS.length; kind++) {
                SplittableRandom random = new SplittableRandom(31L * seed + kind);
                PolygonSoup soup = kind == 0 ? star(random) : kind == 1 ? turnedBox(random) : stretchedOctahedron(random);
                HalfedgeMesh mesh = MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
                String what = KINDS[kind] + " " + seed;
                try {
                    Wrap.Result result = Wrap.wrap(HamiltonianRefinement.refine(mesh), new Wrap.Options(Double.NaN, Double.NaN));
                    List<FoldFile.Folded> sheets = new ArrayList<>();
                    for (Wrap.Strip strip : result.strips()) {
                        sheets.add(new FoldFile.Folded(strip.sheet(), result.frames()));
                    }
                    LayerOrder.Result order = LayerOrder.check(FoldFile.text("bench/RandomSolids", sheets));
                    if (!order.valid()) {
                        broken++;
                        System.out.println(what + ": " + order.summary());
                    }
                    List<PaperInSpace> geometries = new ArrayList<>();
                    for (Wrap.Strip strip : result.strips()) {
                        geometries.add(PaperInSpace.of(strip.sheet(), result.frames()));
                    }
                    PaperCollisions.Result collisions = Collisions.check(geometries, result.thickness(), mesh, null);
                    if (collisions != null && !collisions.isClean()) {
                        colliding[kind]++;
                        System.out.println(what + ": " + collisions.summary());
                    }
                } catch (Wrap.WrapException e) {
                    refused++;
                    System.out.println(what + ": refused: " + e.getMessage());
                }
            }
        }
        System.out.printf("%d solids: %d with a broken layer order, %d refused%n", KINDS.length * n, broken, refused);
        for (int kind = 0; kind < KINDS.length; kind++) {
            System.out.printf("%s: %d of %d collide%n", KINDS[kind], colliding[kind], n);
        }
    }

    static PolygonSoup star(SplittableRandom random) {
        PolygonSoup ico = Solids.icosahedron();
        PolygonSoup soup = new PolygonSoup();
        for (int v = 0; v < ico.vertexCount(); v++) {
            double scale = 0.6 + 0.8 * random.nextDouble();
            soup.addVertex(scale * ico.coordinate(v, 0), scale * ico.coordinate(v, 1), scale * ico.coordinate(v, 2));
        }
        for (int f = 0; f < ico.faceCount(); f++) {
            soup.addFace(new int[] {ico.faceVertex(f, 0), ico.faceVertex(f, 1), ico.faceVertex(f, 2)}, 3, 0);
        }
        return soup;
    }

    static PolygonSoup turnedBox(SplittableRandom random) {
        double[] side = {0.5 + 10 * random.nextDouble(), 0.5 + 3 * random.nextDouble(), 0.5 + 2 * random.nextDouble()};
        double turn = random.nextDouble() * 2 * Math.PI;
        double tilt = random.nextDouble() * 2 * Math.PI;
        PolygonSoup soup = new PolygonSoup();
        for (int x = 0; x < 2; x++) {
            for (int y = 0; y < 2; y++) {
                for (int z = 0; z < 2; z++) {
                    double px = x * side[0];
                    double py = y * side[1];
                    double pz = z * side[2];
                    double rx = Math.cos(turn) * px - Math.sin(turn) * py;
                    double ry = Math.sin(turn) * px + Math.cos(turn) * py;
                    soup.addVertex(rx, Math.cos(tilt) * ry - Math.sin(tilt) * pz, Math.sin(tilt) * ry + Math.cos(tilt) * pz);
                }
            }
        }
        for (int[] quad : new int[][] {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}}) {
            soup.addFace(quad, 4, 0);
        }
        return soup;
    }

    static PolygonSoup stretchedOctahedron(SplittableRandom random) {
        PolygonSoup octahedron = Solids.octahedron();
        double[] scale = {0.3 + 3 * random.nextDouble(), 0.3 + 3 * random.nextDouble(), 0.3 + 3 * random.nextDouble()};
        PolygonSoup soup = new PolygonSoup();
        for (int v = 0; v < octahedron.vertexCount(); v++) {
            soup.addVertex(scale[0] * octahedron.coordinate(v, 0), scale[1] * octahedron.coordinate(v, 1),
                    scale[2] * octahedron.coordinate(v, 2));
        }
        for (int f = 0; f < octahedron.faceCount(); f++) {
            soup.addFace(new int[] {octahedron.faceVertex(f, 0), octahedron.faceVertex(f, 1), octahedron.faceVertex(f, 2)}, 3, 0);
        }
        return soup;
    }
}
