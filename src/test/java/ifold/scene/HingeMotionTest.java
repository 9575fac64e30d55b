package ifold.scene;

import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.check.PaperCollisions;
import ifold.mesh.GridSquares;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.Polycubes;
import ifold.wrap.HingeStrip;
import ifold.wrap.HingeTour;
import ifold.wrap.PaperInSpace;
import ifold.wrap.Wrap;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The hinge strip's folding motion, as the playback shows it, keeps out of the solid: at every
 * fold, at moments all through it, the paper in motion (the square being wrapped as it stands,
 * and the tail swinging about its crease) neither crosses the model nor has a point inside it,
 * by the collision checker reading what is drawn. Before the tail was cut to the square it lands
 * on, its two widths swung into a wall beside the square (the L: 10 moments, the 50 random
 * cubes: 414); only the cube's passed.
 */
class HingeMotionTest {
    static Stream<Object[]> polycubes() {
        List<int[]> slab = new ArrayList<>(Polycubes.box(3, 3, 1));
        slab.add(new int[] {1, 1, 1});
        return Stream.of(new Object[] {"cube", Polycubes.box(1, 1, 1)}, new Object[] {"L", Polycubes.l()},
                new Object[] {"plus", Polycubes.plus()}, new Object[] {"staircase", Polycubes.staircase()},
                new Object[] {"cube on a slab", slab}, new Object[] {"50 random cubes", Polycubes.random(50, 1)});
    }

    /** Moments of each fold looked at: its start, through it, its end. */
    private static final double[] MOMENTS = {0, 0.2, 0.4, 0.6, 0.8, 0.999};

    @ParameterizedTest(name = "{0}")
    @MethodSource("polycubes")
    void theFoldingMotionKeepsOutOfTheSolid(String name, List<int[]> cubes) throws Exception {
        HalfedgeMesh mesh = MeshBuilder.build(Polycubes.surface(cubes), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        GridSquares squares = GridSquares.of(mesh, Double.NaN);
        Wrap.Result result = HingeStrip.wrap(squares, HingeTour.of(squares), Double.NaN, Wrap.DEFAULT_MAX_FACES, Wrap.Watcher.NONE);
        List<PaperInSpace> geometries = List.of(PaperInSpace.of(result.strips().get(0).sheet(), result.frames()));
        Scene scene = new Scene();
        scene.root().attach(new Geometry("model", SceneMesh.of(mesh), Material.PAPER));
        WrapPlayback playback = WrapView.play(scene, result, geometries);
        Geometry[] folding = new Geometry[1];
        scene.root().visitGeometry(g -> {
            if (g.name().equals("folding")) {
                folding[0] = g;
            }
        });
        double[] model = new double[9 * mesh.faceCount()];
        for (int t = 0; t < mesh.faceCount(); t++) {
            for (int c = 0; c < 3; c++) {
                for (int axis = 0; axis < 3; axis++) {
                    model[9 * t + 3 * c + axis] = mesh.coordinate(mesh.faceVertex(t, c), axis);
                }
            }
        }
        int folds = result.steps().size();
        List<String> into = new ArrayList<>();
        for (int j = 0; j < folds; j++) {
            double from = playback.positionAfter(j);
            double to = playback.positionAfter(j + 1);
            for (double moment : MOMENTS) {
                playback.apply(from + moment * (to - from));
                PaperCollisions.Result check = PaperCollisions.check(obj(folding[0].mesh()), result.thickness(), model);
                if (check.modelCrossings() + check.pointsInside() > 0) {
                    into.add(String.format(Locale.ROOT, "fold %d (%s) at %.1f: %s", j + 1, playback.describe(from + moment * (to - from)),
                            moment, check.summary()));
                }
            }
        }
        assertTrue(into.isEmpty(), () -> name + ": " + into.size() + " moments into the solid, the first: " + into.subList(0, Math.min(5, into.size())));
    }

    /** What is drawn, as an OBJ of paper faces. */
    private static String obj(SceneMesh drawn) {
        StringBuilder text = new StringBuilder("o strip-1\n");
        double[] p = drawn.positions();
        for (int v = 0; v < drawn.vertexCount(); v++) {
            text.append("v ").append(p[3 * v]).append(' ').append(p[3 * v + 1]).append(' ').append(p[3 * v + 2]).append('\n');
        }
        text.append("g paper\n");
        int[] t = drawn.triangles();
        for (int k = 0; k < drawn.triangleCount(); k++) {
            text.append("f ").append(t[3 * k] + 1).append(' ').append(t[3 * k + 1] + 1).append(' ').append(t[3 * k + 2] + 1).append('\n');
        }
        return text.toString();
    }
}
