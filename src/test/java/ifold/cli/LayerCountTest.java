package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The report's {@code maxLayers} against a count by brute force from the exported FOLD file
 * alone: the faces of each plane, and for every slab between two x's where an arrangement vertex
 * lies (a face's corner, two edges crossing), the faces the slab's middle line meets, as
 * intervals, swept for the most at once. Within a slab nothing changes but the line's place,
 * so the most faces over any point of the plane is the most over the slabs' middle lines.
 */
class LayerCountTest {
    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(strings = {"wrap models/tetrahedron.off", "wrap models/cube.off", "wrap models/octahedron.off", "demo zigzag",
        "demo turn --angle 70", "fold models/scripts/pleat20.fold", "fold models/scripts/square-quarters.fold"})
    void theReportsMostLayersAreTheFaceCountsMost(String command) throws Exception {
        Path fold = dir.resolve("out.fold");
        Path report = dir.resolve("r.json");
        List<String> args = new ArrayList<>(Arrays.asList(command.split(" ")));
        args.addAll(List.of("--no-view", "--export-fold", fold.toString(), "--report", report.toString()));
        CliTest.Run run = CliTest.run(args.toArray(String[]::new));
        assertEquals(0, run.code(), run.err());
        int reported = (int) CliTest.number(Files.readString(report), "maxLayers");
        int counted = mostFacesOverAPoint(fold);
        assertTrue(counted >= 2, "setup: paper folded over itself, got " + counted);
        assertEquals(counted, reported, command + ": the report's maxLayers against the faces of the FOLD file counted");
    }

    /** The most faces of the folded state over any point of one plane, from the FOLD file alone. */
    @SuppressWarnings("unchecked")
    static int mostFacesOverAPoint(Path file) throws Exception {
        Map<String, Object> fold = (Map<String, Object>) ifold.foldfile.FoldFileTest.read(file);
        List<?> faces = (List<?>) fold.get("faces_vertices");
        List<?> frames = (List<?>) fold.get("file_frames");
        List<?> folded = (List<?>) ((Map<?, ?>) frames.get(0)).get("vertices_coords");
        double[][] xyz = new double[folded.size()][3];
        double size = 0;
        for (int v = 0; v < folded.size(); v++) {
            List<?> p = (List<?>) folded.get(v);
            for (int axis = 0; axis < 3; axis++) {
                xyz[v][axis] = p.size() > axis ? ((Number) p.get(axis)).doubleValue() : 0;
                size = Math.max(size, Math.abs(xyz[v][axis]));
            }
        }
        // Faces by plane: Newell's normal made unit, its sign fixed, and the plane's offset, each
        // within a tolerance of a plane met before (not rounded to keys, which split a plane
        // whose offset falls at a rounding boundary).
        List<List<double[][]>> planes = new ArrayList<>();
        List<double[]> normals = new ArrayList<>(); // nx, ny, nz, offset
        for (Object face : faces) {
            List<?> loop = (List<?>) face;
            double[] n = new double[3];
            double[][] corners = new double[loop.size()][];
            for (int k = 0; k < loop.size(); k++) {
                double[] a = xyz[((Number) loop.get(k)).intValue()];
                double[] b = xyz[((Number) loop.get((k + 1) % loop.size())).intValue()];
                n[0] += (a[1] - b[1]) * (a[2] + b[2]);
                n[1] += (a[2] - b[2]) * (a[0] + b[0]);
                n[2] += (a[0] - b[0]) * (a[1] + b[1]);
                corners[k] = a;
            }
            double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (!(length > 0)) {
                continue;
            }
            // The sign from the first component of more than half the length (a unit normal has
            // one of at least 0.577): the largest flips between equal ones by rounding, and the
            // tetrahedron's four planes came out as seven.
            int big = Math.abs(n[0]) > 0.5 * length ? 0 : Math.abs(n[1]) > 0.5 * length ? 1 : 2;
            double sign = n[big] < 0 ? -1 : 1;
            for (int axis = 0; axis < 3; axis++) {
                n[axis] *= sign / length;
            }
            double offset = n[0] * corners[0][0] + n[1] * corners[0][1] + n[2] * corners[0][2];
            int found = -1;
            for (int q = 0; q < normals.size() && found < 0; q++) {
                double[] m = normals.get(q);
                if (n[0] * m[0] + n[1] * m[1] + n[2] * m[2] > 1 - 1e-9 && Math.abs(offset - m[3]) <= 1e-7 * Math.max(size, 1e-300)) {
                    found = q;
                }
            }
            if (found < 0) {
                found = planes.size();
                planes.add(new ArrayList<>());
                normals.add(new double[] {n[0], n[1], n[2], offset});
            }
            planes.get(found).add(corners);
        }
        int most = 0;
        for (int q = 0; q < planes.size(); q++) {
            most = Math.max(most, mostOnPlane(planes.get(q), normals.get(q), size));
        }
        return most;
    }

    private static int mostOnPlane(List<double[][]> faces, double[] n, double size) {
        // A basis of the plane.
        double[] u = Math.abs(n[0]) < 0.9 ? new double[] {0, -n[2], n[1]} : new double[] {n[2], 0, -n[0]};
        double ul = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (int axis = 0; axis < 3; axis++) {
            u[axis] /= ul;
        }
        double[] w = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
        List<double[]> polygons = new ArrayList<>(); // x0 y0 x1 y1 ...
        for (double[][] face : faces) {
            double[] p = new double[2 * face.length];
            for (int k = 0; k < face.length; k++) {
                p[2 * k] = face[k][0] * u[0] + face[k][1] * u[1] + face[k][2] * u[2];
                p[2 * k + 1] = face[k][0] * w[0] + face[k][1] * w[1] + face[k][2] * w[2];
            }
            polygons.add(p);
        }
        double eps = 1e-9 * Math.max(size, 1e-300);
        // Every x where the arrangement has a vertex: corners, and edges crossing.
        List<double[]> edges = new ArrayList<>();
        List<Double> xs = new ArrayList<>();
        for (double[] p : polygons) {
            int m = p.length / 2;
            for (int k = 0; k < m; k++) {
                xs.add(p[2 * k]);
                edges.add(new double[] {p[2 * k], p[2 * k + 1], p[2 * ((k + 1) % m)], p[2 * ((k + 1) % m) + 1]});
            }
        }
        for (int i = 0; i < edges.size(); i++) {
            double[] a = edges.get(i);
            for (int j = i + 1; j < edges.size(); j++) {
                double[] b = edges.get(j);
                double dax = a[2] - a[0];
                double day = a[3] - a[1];
                double dbx = b[2] - b[0];
                double dby = b[3] - b[1];
                double denominator = dax * dby - day * dbx;
                if (denominator == 0) {
                    continue;
                }
                double s = ((b[0] - a[0]) * dby - (b[1] - a[1]) * dbx) / denominator;
                double t = ((b[0] - a[0]) * day - (b[1] - a[1]) * dax) / denominator;
                if (s > 0 && s < 1 && t > 0 && t < 1) {
                    xs.add(a[0] + s * dax);
                }
            }
        }
        double[] sorted = xs.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        int most = 0;
        for (int k = 0; k + 1 < sorted.length; k++) {
            if (sorted[k + 1] - sorted[k] <= eps) {
                continue;
            }
            double x = (sorted[k] + sorted[k + 1]) / 2;
            List<double[]> events = new ArrayList<>(); // y, +1 opening or -1 closing
            for (double[] p : polygons) {
                double low = Double.POSITIVE_INFINITY;
                double high = Double.NEGATIVE_INFINITY;
                int m = p.length / 2;
                for (int e = 0; e < m; e++) {
                    double x0 = p[2 * e];
                    double y0 = p[2 * e + 1];
                    double x1 = p[2 * ((e + 1) % m)];
                    double y1 = p[2 * ((e + 1) % m) + 1];
                    if ((x0 - x) * (x1 - x) < 0) {
                        double y = y0 + (x - x0) / (x1 - x0) * (y1 - y0);
                        low = Math.min(low, y);
                        high = Math.max(high, y);
                    }
                }
                if (high - low > eps) { // a face thinner than the tolerance there adds no layer
                    events.add(new double[] {low + eps / 2, 1});
                    events.add(new double[] {high - eps / 2, -1});
                }
            }
            events.sort((a, b) -> a[0] != b[0] ? Double.compare(a[0], b[0]) : Double.compare(a[1], b[1]));
            int open = 0;
            for (double[] event : events) {
                open += (int) event[1];
                most = Math.max(most, open);
            }
        }
        return most;
    }
}
