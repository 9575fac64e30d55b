package ifold.fold;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.InvalidMeshException;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A folded (or flat) sheet of paper: convex faces over vertices that each know their 3D position
 * and their paper coordinates. Faces are listed counter-clockwise seen from the paper's top side
 * as it was before folding, so a face turned over shows its bottom to the top. Cap faces are the
 * bent paper at a fold's edge: they are drawn but are not part of the flat sheet.
 *
 * <p>Immutable: a fold makes a new paper. Small by nature (a fold adds a few faces per layer),
 * so faces are kept as one {@code int[]} each.
 */
public final class Paper {
    /** x, y, z of each vertex. */
    final double[] positions;
    /** u, v of each vertex: where it lies on the unfolded sheet. */
    final double[] paperCoordinates;
    final List<int[]> faces;
    /** Whether each face is a cap facet. */
    final boolean[] cap;
    final double thickness;
    /** The normal of the unfolded sheet's top side; every flat layer is perpendicular to it. */
    final Vector3d normal;
    /** Edges that are creases, as vertex pairs (lower vertex first), for drawing and counting. */
    final List<long[]> creases;

    Paper(double[] positions, double[] paperCoordinates, List<int[]> faces, boolean[] cap, double thickness,
            Vector3dc normal, List<long[]> creases) {
        this.positions = positions;
        this.paperCoordinates = paperCoordinates;
        this.faces = List.copyOf(faces);
        this.cap = cap;
        this.thickness = thickness;
        this.normal = new Vector3d(normal);
        this.creases = List.copyOf(creases);
    }

    /** A flat rectangle [0, width] × [0, height] in the plane z = 0, top side up, paper coordinates = x, y. */
    public static Paper rectangle(double width, double height, double thickness) {
        if (!(width > 0) || !(height > 0) || !Double.isFinite(width) || !Double.isFinite(height)) {
            throw new IllegalArgumentException("paper must have a positive width and height, got " + width + " by " + height);
        }
        if (!(thickness >= 0) || !Double.isFinite(thickness)) {
            throw new IllegalArgumentException("paper thickness must be zero or more, got " + thickness);
        }
        double[] xyz = {0, 0, 0, width, 0, 0, width, height, 0, 0, height, 0};
        double[] uv = {0, 0, width, 0, width, height, 0, height};
        List<int[]> faces = new ArrayList<>();
        faces.add(new int[] {0, 1, 2, 3});
        return new Paper(xyz, uv, faces, new boolean[1], thickness, new Vector3d(0, 0, 1), List.of());
    }

    /** A strip of paper: a long rectangle along x. */
    public static Paper strip(double length, double width, double thickness) {
        return rectangle(length, width, thickness);
    }

    public static Paper square(double side, double thickness) {
        return rectangle(side, side, thickness);
    }

    /**
     * This paper moved rigidly by {@code motion} (a rotation and a translation, no scaling or
     * mirroring): its paper coordinates stay, its positions and normal move.
     *
     * @throws IllegalArgumentException if {@code motion} is not rigid
     */
    public Paper moved(org.joml.Matrix4dc motion) {
        org.joml.Matrix3d rotation = motion.get3x3(new org.joml.Matrix3d());
        org.joml.Matrix3d check = new org.joml.Matrix3d(rotation).transpose().mul(rotation);
        if (!check.equals(new org.joml.Matrix3d(), 1e-9) || !(Math.abs(rotation.determinant() - 1) < 1e-9)) {
            throw new IllegalArgumentException("paper moves rigidly: the motion must be a rotation and a translation");
        }
        double[] xyz = new double[positions.length];
        Vector3d p = new Vector3d();
        for (int v = 0; v < vertexCount(); v++) {
            motion.transformPosition(p.set(x(v), y(v), z(v)));
            xyz[3 * v] = p.x;
            xyz[3 * v + 1] = p.y;
            xyz[3 * v + 2] = p.z;
        }
        Vector3d movedNormal = rotation.transform(new Vector3d(normal)).normalize();
        return new Paper(xyz, paperCoordinates, faces, cap, thickness, movedNormal, creases);
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    public int faceCount() {
        return faces.size();
    }

    /** The vertices of face {@code f}, counter-clockwise seen from the paper's original top. */
    public int[] face(int f) {
        return faces.get(f).clone();
    }

    public boolean isCap(int f) {
        return cap[f];
    }

    public double thickness() {
        return thickness;
    }

    /** The unfolded sheet's top normal. */
    public Vector3dc normal() {
        return normal;
    }

    public double x(int v) {
        return positions[3 * v];
    }

    public double y(int v) {
        return positions[3 * v + 1];
    }

    public double z(int v) {
        return positions[3 * v + 2];
    }

    /** Paper coordinate u of vertex {@code v}. */
    public double u(int v) {
        return paperCoordinates[2 * v];
    }

    /** Paper coordinate v of vertex {@code v}. */
    public double v(int v) {
        return paperCoordinates[2 * v + 1];
    }

    /** Height of vertex {@code v} along the sheet's normal. */
    public double height(int v) {
        return normal.x * x(v) + normal.y * y(v) + normal.z * z(v);
    }

    /** The creases: fold lines, as pairs of vertices. */
    public int creaseCount() {
        return creases.size();
    }

    public List<int[]> creaseEdges() {
        List<int[]> edges = new ArrayList<>();
        for (long[] crease : creases) {
            edges.add(new int[] {(int) crease[0], (int) crease[1]});
        }
        return edges;
    }

    /** The largest extent of the sheet in paper coordinates, which scales its tolerances. */
    public double size() {
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (double c : paperCoordinates) {
            min = Math.min(min, c);
            max = Math.max(max, c);
        }
        return max - min;
    }

    /** The paper faces and caps as a polygon soup (faces in order), positions in 3D. */
    public PolygonSoup soup() {
        PolygonSoup soup = new PolygonSoup();
        for (int v = 0; v < vertexCount(); v++) {
            soup.addVertex(x(v), y(v), z(v));
        }
        for (int[] face : faces) {
            soup.addFace(face, face.length, 0);
        }
        return soup;
    }

    /**
     * The top side as a halfedge mesh, built strictly: a fold that left the sheet torn, twisted
     * or with a sliver would be refused here. The bottom side is the same mesh with every face
     * reversed, which {@link #bottom()} gives.
     */
    public HalfedgeMesh top() throws InvalidMeshException {
        return MeshBuilder.build(soup(), new MeshBuilder.Options(true, false)).mesh();
    }

    /** The bottom side: the top mirrored, the same vertices with every face reversed. */
    public HalfedgeMesh bottom() throws InvalidMeshException {
        PolygonSoup soup = new PolygonSoup();
        for (int v = 0; v < vertexCount(); v++) {
            soup.addVertex(x(v), y(v), z(v));
        }
        for (int[] face : faces) {
            int[] reversed = new int[face.length];
            for (int i = 0; i < face.length; i++) {
                reversed[i] = face[face.length - 1 - i];
            }
            soup.addFace(reversed, reversed.length, 0);
        }
        return MeshBuilder.build(soup, new MeshBuilder.Options(true, false)).mesh();
    }

    double[] positionsCopy() {
        return Arrays.copyOf(positions, positions.length);
    }
}
