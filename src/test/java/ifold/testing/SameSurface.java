package ifold.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.geom.Triangles;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshValidator;
import java.util.List;

/** That a mesh made from a model (its faces triangulated again) is the model's surface, checked from the two meshes alone. */
public final class SameSurface {
    private SameSurface() {
    }

    /**
     * The prepared mesh is the model's surface: valid, of the same topology and area, each
     * vertex on a face of the model, each triangle's centroid on one too, and each edge where
     * the prepared surface bends lying on an edge of the model (a crease kept, none made).
     */
    public static void assertSameSurface(HalfedgeMesh model, HalfedgeMesh prepared) {
        assertEquals(List.of(), MeshValidator.validate(prepared));
        assertEquals(model.vertexCount() - model.edgeCount() + model.faceCount(),
                prepared.vertexCount() - prepared.edgeCount() + prepared.faceCount(), "Euler characteristic");
        assertEquals(area(model), area(prepared), 1e-9 * area(model), "area");
        double size = 0;
        for (int v = 0; v < model.vertexCount(); v++) {
            for (int axis = 0; axis < 3; axis++) {
                size = Math.max(size, Math.abs(model.coordinate(v, axis)));
            }
        }
        double tolerance = 1e-9 * size;
        for (int v = 0; v < prepared.vertexCount(); v++) {
            double[] p = {prepared.x(v), prepared.y(v), prepared.z(v)};
            assertTrue(onModel(model, p, tolerance), "vertex " + v + " off the model");
        }
        for (int f = 0; f < prepared.faceCount(); f++) {
            int h = prepared.faceHalfedge(f);
            int[] c = {prepared.fromVertex(h), prepared.toVertex(h), prepared.toVertex(prepared.next(h))};
            double[] centroid = new double[3];
            for (int k = 0; k < 3; k++) {
                for (int axis = 0; axis < 3; axis++) {
                    centroid[axis] += prepared.coordinate(c[k], axis) / 3;
                }
            }
            assertTrue(onModel(model, centroid, tolerance), "triangle " + f + " off the model");
        }
        double creases = 0;
        for (int e = 0; e < prepared.edgeCount(); e++) {
            int h = HalfedgeMesh.halfedgeOfEdge(e, 0);
            if (prepared.isBoundaryEdge(e) || coplanarAcross(prepared, h)) {
                continue;
            }
            double[] a = {prepared.x(prepared.fromVertex(h)), prepared.y(prepared.fromVertex(h)), prepared.z(prepared.fromVertex(h))};
            double[] b = {prepared.x(prepared.toVertex(h)), prepared.y(prepared.toVertex(h)), prepared.z(prepared.toVertex(h))};
            assertTrue(onModelEdge(model, a, b, tolerance), "a crease of the prepared surface off the model's edges at edge " + e);
            creases += Math.sqrt(sq(a[0] - b[0]) + sq(a[1] - b[1]) + sq(a[2] - b[2]));
        }
        double modelCreases = 0;
        for (int e = 0; e < model.edgeCount(); e++) {
            int h = HalfedgeMesh.halfedgeOfEdge(e, 0);
            if (!model.isBoundaryEdge(e) && !coplanarAcross(model, h)) {
                modelCreases += length(model, h);
            }
        }
        assertEquals(modelCreases, creases, 1e-9 * Math.max(1, modelCreases), "the creases' length");
    }

    private static boolean coplanarAcross(HalfedgeMesh mesh, int h) {
        double[] n = normal(mesh, mesh.face(h));
        double[] m = normal(mesh, mesh.face(HalfedgeMesh.twin(h)));
        return n[0] * m[0] + n[1] * m[1] + n[2] * m[2] > 1 - 1e-12;
    }

    private static double[] normal(HalfedgeMesh mesh, int f) {
        int h = mesh.faceHalfedge(f);
        int a = mesh.fromVertex(h);
        int b = mesh.toVertex(h);
        int c = mesh.toVertex(mesh.next(h));
        double[] u = {mesh.x(b) - mesh.x(a), mesh.y(b) - mesh.y(a), mesh.z(b) - mesh.z(a)};
        double[] v = {mesh.x(c) - mesh.x(a), mesh.y(c) - mesh.y(a), mesh.z(c) - mesh.z(a)};
        double[] n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        return new double[] {n[0] / length, n[1] / length, n[2] / length};
    }

    /** Whether p lies on a triangle of the model (within tolerance of its plane, inside its edges). */
    private static boolean onModel(HalfedgeMesh model, double[] p, double tolerance) {
        for (int f = 0; f < model.faceCount(); f++) {
            int h = model.faceHalfedge(f);
            int[] c = {model.fromVertex(h), model.toVertex(h), model.toVertex(model.next(h))};
            double[] n = normal(model, f);
            double d = 0;
            for (int axis = 0; axis < 3; axis++) {
                d += n[axis] * (p[axis] - model.coordinate(c[0], axis));
            }
            if (Math.abs(d) > tolerance) {
                continue;
            }
            boolean inside = true;
            for (int k = 0; k < 3 && inside; k++) {
                int a = c[k];
                int b = c[(k + 1) % 3];
                double[] edge = {model.x(b) - model.x(a), model.y(b) - model.y(a), model.z(b) - model.z(a)};
                double[] toP = {p[0] - model.x(a), p[1] - model.y(a), p[2] - model.z(a)};
                double[] cross = {edge[1] * toP[2] - edge[2] * toP[1], edge[2] * toP[0] - edge[0] * toP[2], edge[0] * toP[1] - edge[1] * toP[0]};
                inside = cross[0] * n[0] + cross[1] * n[1] + cross[2] * n[2] >= -tolerance * Math.sqrt(edge[0] * edge[0] + edge[1] * edge[1] + edge[2] * edge[2]);
            }
            if (inside) {
                return true;
            }
        }
        return false;
    }

    /** Whether segment ab lies along one edge of the model. */
    private static boolean onModelEdge(HalfedgeMesh model, double[] a, double[] b, double tolerance) {
        for (int e = 0; e < model.edgeCount(); e++) {
            int h = HalfedgeMesh.halfedgeOfEdge(e, 0);
            double[] p = {model.x(model.fromVertex(h)), model.y(model.fromVertex(h)), model.z(model.fromVertex(h))};
            double[] q = {model.x(model.toVertex(h)), model.y(model.toVertex(h)), model.z(model.toVertex(h))};
            if (onSegment(p, q, a, tolerance) && onSegment(p, q, b, tolerance)) {
                return true;
            }
        }
        return false;
    }

    private static boolean onSegment(double[] p, double[] q, double[] x, double tolerance) {
        double[] d = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        double len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        double t = ((x[0] - p[0]) * d[0] + (x[1] - p[1]) * d[1] + (x[2] - p[2]) * d[2]) / len2;
        if (t < -1e-12 || t > 1 + 1e-12) {
            return false;
        }
        double distance2 = 0;
        for (int axis = 0; axis < 3; axis++) {
            distance2 += sq(p[axis] + t * d[axis] - x[axis]);
        }
        return Math.sqrt(distance2) <= tolerance;
    }

    private static double area(HalfedgeMesh mesh) {
        double area = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            int h = mesh.faceHalfedge(f);
            area += Triangles.twiceArea(mesh.positionArray(), mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h))) / 2;
        }
        return area;
    }

    private static double length(HalfedgeMesh mesh, int h) {
        int a = mesh.fromVertex(h);
        int b = mesh.toVertex(h);
        return Math.sqrt(sq(mesh.x(a) - mesh.x(b)) + sq(mesh.y(a) - mesh.y(b)) + sq(mesh.z(a) - mesh.z(b)));
    }

    private static double sq(double x) {
        return x * x;
    }
}
