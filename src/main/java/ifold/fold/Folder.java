package ifold.fold;

import ifold.geom.Plane;
import ifold.geom.Tolerance;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Makes folds, the seed's way:
 * <ol>
 *   <li>the fold plane contains the fold line and stands perpendicular to the paper; it slices
 *       through every layer;</li>
 *   <li>edges that cross it are split at the exact crossing (3D position and paper coordinates
 *       at the same fraction, so the pieces stay isometric), and faces that cross it are cut in
 *       two; vertices within {@link ifold.geom.Tolerance#ON_PLANE} of it are used as they are,
 *       so folds through vertices and along creases make no slivers;</li>
 *   <li>the faces on the moving side move; the vertices on the fold line that they share with
 *       faces that stay are cloned for them;</li>
 *   <li>the moving region turns about an axis parallel to the fold line, lifted above the top
 *       layer at the line (valley) or below the bottom one (mountain) by half a thickness, so
 *       that after a flat fold the layers lie exactly one thickness apart and in reverse order;</li>
 *   <li>the fold's edge is a cap of two facets: each fold-line vertex gets a third clone that
 *       turns half as far, and two quads join the layer that stays, the half-turned clones and
 *       the layer that moved. With zero thickness there is no gap and no cap.</li>
 * </ol>
 * A fold is made in two parts so that it can be animated: {@link #prepare} does the cutting and
 * cloning, and {@link Prepared#at(double)} turns the moving part any fraction of the way.
 */
public final class Folder {
    private Folder() {
    }

    /** Makes the whole fold. */
    public static Paper fold(Paper paper, Fold fold) throws FoldException {
        return prepare(paper, fold).at(1);
    }

    /**
     * A fold cut and cloned, ready to turn.
     *
     * @param paper the paper after cutting, cloning and capping, nothing turned yet
     * @param moving the vertices that turn all the way
     * @param half the cap vertices that turn half way
     * @param axisPoint a point of the axis
     * @param axisDirection the axis's unit direction: turning is counter-clockwise about it
     * @param angle the full turn, in radians
     */
    public record Prepared(Paper paper, int[] moving, int[] half, Vector3dc axisPoint, Vector3dc axisDirection, double angle)
            implements PaperMotion {
        /** The paper with the moving part turned {@code fraction} of the way (0 = not at all, 1 = the fold made). */
        @Override
        public Paper at(double fraction) {
            double[] xyz = paper.positionsCopy();
            rotate(xyz, moving, fraction * angle);
            rotate(xyz, half, fraction * angle / 2);
            return new Paper(xyz, paper.paperCoordinates, paper.faces, paper.cap, paper.thickness, paper.normal,
                    paper.creases);
        }

        private void rotate(double[] xyz, int[] vertices, double radians) {
            if (radians == 0) {
                return;
            }
            // Rodrigues' rotation about the axis through axisPoint.
            double c = Math.cos(radians);
            double s = Math.sin(radians);
            double kx = axisDirection.x();
            double ky = axisDirection.y();
            double kz = axisDirection.z();
            for (int v : vertices) {
                double px = xyz[3 * v] - axisPoint.x();
                double py = xyz[3 * v + 1] - axisPoint.y();
                double pz = xyz[3 * v + 2] - axisPoint.z();
                double dot = kx * px + ky * py + kz * pz;
                double cx = ky * pz - kz * py;
                double cy = kz * px - kx * pz;
                double cz = kx * py - ky * px;
                xyz[3 * v] = axisPoint.x() + px * c + cx * s + kx * dot * (1 - c);
                xyz[3 * v + 1] = axisPoint.y() + py * c + cy * s + ky * dot * (1 - c);
                xyz[3 * v + 2] = axisPoint.z() + pz * c + cz * s + kz * dot * (1 - c);
            }
        }
    }

    /** Cuts the paper along the fold and clones what the fold needs; see the class documentation. */
    public static Prepared prepare(Paper paper, Fold fold) throws FoldException {
        if (!(fold.angleDegrees() > 0 && fold.angleDegrees() <= 180)) {
            throw new FoldException("the angle must be more than 0 and at most 180 degrees, got " + fold.angleDegrees());
        }
        Vector3dc n = paper.normal;
        Vector3d direction = new Vector3d(fold.direction());
        direction.fma(-direction.dot(n), n); // only the part along the paper
        if (!(direction.length() > 1e-12 * Math.max(1, fold.direction().length()))) {
            throw new FoldException("the fold line must run along the paper, not across it");
        }
        direction.normalize();
        // Right of the line, seen from the top with the line pointing ahead, is direction × n.
        Vector3d side = direction.cross(n, new Vector3d());
        if (fold.moving() == Fold.Side.LEFT) {
            side.negate();
        }
        Vector3dc p = fold.point();
        Plane plane = Plane.through(p.x(), p.y(), p.z(), side.x, side.y, side.z, paper.size());
        Cutter cutter = new Cutter(paper, (x, y, z, u, v) -> plane.distance(x, y, z), plane.tolerance());
        cutter.cut();
        if (!cutter.anyAbove) {
            throw new FoldException("nothing moves: the line misses the paper, or no paper lies on the "
                    + fold.moving().name().toLowerCase(java.util.Locale.ROOT) + " of it");
        }
        if (!cutter.anyBelow) {
            throw new FoldException("everything would move: the line misses the paper, or all of it lies on the "
                    + fold.moving().name().toLowerCase(java.util.Locale.ROOT) + " of it");
        }
        return cutter.assemble(fold.kind(), fold.angleDegrees(), fold.point(), side);
    }

    /** Makes the whole flap fold. */
    public static Paper fold(Paper paper, FlapFold fold) throws FoldException {
        return prepare(paper, fold).at(1);
    }

    /**
     * Cuts the paper along a flap fold's crease and clones what the fold needs. The crease's
     * place in space is where the paper it crosses lies now; every point of it must lie on one
     * straight line there, which holds where that paper is flat.
     */
    public static Prepared prepare(Paper paper, FlapFold fold) throws FoldException {
        if (!(fold.angleDegrees() > 0 && fold.angleDegrees() <= 180)) {
            throw new FoldException("the angle must be more than 0 and at most 180 degrees, got " + fold.angleDegrees());
        }
        double du = fold.u2() - fold.u1();
        double dv = fold.v2() - fold.v1();
        double length = Math.hypot(du, dv);
        if (!(length > 0) || !Double.isFinite(length)) {
            throw new FoldException("the crease's two paper points must differ");
        }
        // Right of the line on the sheet, seen from its top, is (dv, -du).
        double sign = fold.moving() == Fold.Side.RIGHT ? 1 : -1;
        double a = sign * dv / length;
        double b = -sign * du / length;
        double c = a * fold.u1() + b * fold.v1();
        Cutter cutter = new Cutter(paper, (x, y, z, u, v) -> a * u + b * v - c, Tolerance.ON_PLANE * paper.size());
        cutter.cut();
        if (!cutter.anyAbove || !cutter.anyBelow) {
            throw new FoldException((cutter.anyAbove ? "everything" : "nothing") + " would move: the crease misses the paper");
        }
        return cutter.assembleFlap(fold);
    }

    /** Signed distance of a vertex from a fold's dividing line or plane: positive on the moving side. */
    @FunctionalInterface
    private interface Divider {
        double distance(double x, double y, double z, double u, double v);
    }

    /** The cutting and cloning of one fold. */
    private static final class Cutter {
        private final Paper paper;
        private final Divider divider;
        private final double tolerance;
        private double[] xyz;
        private double[] uv;
        private int vertexCount;
        /** Side of each vertex: ABOVE is the moving side. */
        private Plane.Side[] sides;
        private final List<int[]> faces = new ArrayList<>();
        private final List<Boolean> caps = new ArrayList<>();
        private final List<long[]> creases = new ArrayList<>();
        boolean anyAbove;
        boolean anyBelow;

        Cutter(Paper paper, Divider divider, double tolerance) {
            this.paper = paper;
            this.divider = divider;
            this.tolerance = tolerance;
            vertexCount = paper.vertexCount();
            xyz = Arrays.copyOf(paper.positions, 3 * vertexCount + 48);
            uv = Arrays.copyOf(paper.paperCoordinates, 2 * vertexCount + 32);
            sides = new Plane.Side[vertexCount + 16];
            for (int v = 0; v < vertexCount; v++) {
                double d = distance(v);
                sides[v] = d > tolerance ? Plane.Side.ABOVE : d < -tolerance ? Plane.Side.BELOW : Plane.Side.ON;
            }
        }

        private double distance(int v) {
            return divider.distance(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2], uv[2 * v], uv[2 * v + 1]);
        }

        private int addVertex(double x, double y, double z, double u, double w, Plane.Side side) {
            if (3 * vertexCount + 3 > xyz.length) {
                xyz = Arrays.copyOf(xyz, 2 * xyz.length);
                uv = Arrays.copyOf(uv, 2 * uv.length);
                sides = Arrays.copyOf(sides, 2 * sides.length);
            }
            xyz[3 * vertexCount] = x;
            xyz[3 * vertexCount + 1] = y;
            xyz[3 * vertexCount + 2] = z;
            uv[2 * vertexCount] = u;
            uv[2 * vertexCount + 1] = w;
            sides[vertexCount] = side;
            return vertexCount++;
        }

        private int copyVertex(int v) {
            return addVertex(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2], uv[2 * v], uv[2 * v + 1], sides[v]);
        }

        /** Splits every crossing edge once (shared by the faces on both sides) and cuts the faces. */
        void cut() {
            Map<Long, Integer> splitOfEdge = new HashMap<>();
            for (int f = 0; f < paper.faceCount(); f++) {
                if (paper.cap[f]) {
                    continue;
                }
                int[] face = paper.faces.get(f);
                int[] loop = new int[2 * face.length];
                int size = 0;
                for (int i = 0; i < face.length; i++) {
                    int a = face[i];
                    int b = face[(i + 1) % face.length];
                    loop[size++] = a;
                    if (crosses(sides[a], sides[b])) {
                        long key = edgeKey(a, b);
                        Integer split = splitOfEdge.get(key);
                        if (split == null) {
                            split = splitEdge(Math.min(a, b), Math.max(a, b));
                            splitOfEdge.put(key, split);
                        }
                        loop[size++] = split;
                    }
                }
                addCutFace(Arrays.copyOf(loop, size), false);
            }
            cutCaps(splitOfEdge);
            for (long[] crease : paper.creases) {
                long key = (crease[0] << 32) | crease[1];
                Integer split = splitOfEdge.get(key);
                if (split == null) {
                    creases.add(crease);
                } else {
                    creases.add(new long[] {Math.min(crease[0], split), Math.max(crease[0], split)});
                    creases.add(new long[] {Math.min(crease[1], split), Math.max(crease[1], split)});
                }
            }
        }

        private static long edgeKey(int a, int b) {
            return ((long) Math.min(a, b) << 32) | Math.max(a, b);
        }

        /**
         * Cuts the caps the way their paper was cut, not by the plane: a cap is a strip of quads
         * between parallel rows (the crease on one layer, the bend, the crease on the other), so
         * where a row's paper edge was split, the facing row is split at the same fraction and
         * the quad falls into two quads, each going with its layers. A cap the plane crosses where
         * its paper was not cut (a bulge reaching over the line) stays whole: it goes with the
         * layers it joins. Cutting caps by the plane would slice their thin, slanted quads at
         * places that match nothing, where creases meet.
         */
        private void cutCaps(Map<Long, Integer> splitOfEdge) {
            List<int[]> capLoops = new ArrayList<>();
            for (int f = 0; f < paper.faceCount(); f++) {
                if (paper.cap[f]) {
                    capLoops.add(paper.faces.get(f));
                }
            }
            // Carry each split across its quad to the facing edge; twice, so that a split made on
            // a shared bend row reaches the cap's other facet.
            for (int round = 0; round < 2; round++) {
                for (int[] quad : capLoops) {
                    if (quad.length != 4) {
                        continue;
                    }
                    for (int i = 0; i < 4; i++) {
                        int a = quad[i];
                        int b = quad[(i + 1) % 4];
                        int c = quad[(i + 2) % 4];
                        int d = quad[(i + 3) % 4];
                        Integer split = splitOfEdge.get(edgeKey(a, b));
                        if (split == null || splitOfEdge.containsKey(edgeKey(c, d))) {
                            continue;
                        }
                        // The split lies at fraction t from a to b; the facing edge runs from d to c.
                        double length = Math.hypot(uv[2 * b] - uv[2 * a], uv[2 * b + 1] - uv[2 * a + 1]);
                        double t = length > 0 ? Math.hypot(uv[2 * split] - uv[2 * a], uv[2 * split + 1] - uv[2 * a + 1]) / length
                                : new Vector3d(xyz[3 * split] - xyz[3 * a], xyz[3 * split + 1] - xyz[3 * a + 1],
                                        xyz[3 * split + 2] - xyz[3 * a + 2]).length()
                                        / Math.max(1e-300, position(b).distance(position(a)));
                        int facing = addVertex(
                                xyz[3 * d] + t * (xyz[3 * c] - xyz[3 * d]),
                                xyz[3 * d + 1] + t * (xyz[3 * c + 1] - xyz[3 * d + 1]),
                                xyz[3 * d + 2] + t * (xyz[3 * c + 2] - xyz[3 * d + 2]),
                                uv[2 * d] + t * (uv[2 * c] - uv[2 * d]),
                                uv[2 * d + 1] + t * (uv[2 * c + 1] - uv[2 * d + 1]),
                                Plane.Side.ON);
                        splitOfEdge.put(edgeKey(c, d), facing);
                    }
                }
            }
            for (int[] quad : capLoops) {
                int[] loop = new int[2 * quad.length];
                int size = 0;
                int first = -1;
                int second = -1;
                for (int i = 0; i < quad.length; i++) {
                    loop[size++] = quad[i];
                    Integer split = splitOfEdge.get(edgeKey(quad[i], quad[(i + 1) % quad.length]));
                    if (split != null) {
                        if (first < 0) {
                            first = size;
                        } else {
                            second = size;
                        }
                        loop[size++] = split;
                    }
                }
                loop = Arrays.copyOf(loop, size);
                if (second < 0) {
                    faces.add(loop);
                    caps.add(true);
                } else {
                    faces.add(slice(loop, first, second));
                    caps.add(true);
                    faces.add(slice(loop, second, first));
                    caps.add(true);
                }
            }
        }

        /** The vertices of {@code loop} from index {@code from} to {@code to}, both included, going forward. */
        private static int[] slice(int[] loop, int from, int to) {
            int length = Math.floorMod(to - from, loop.length) + 1;
            int[] part = new int[length];
            for (int i = 0; i < length; i++) {
                part[i] = loop[(from + i) % loop.length];
            }
            return part;
        }

        private static boolean crosses(Plane.Side a, Plane.Side b) {
            return a == Plane.Side.ABOVE && b == Plane.Side.BELOW || a == Plane.Side.BELOW && b == Plane.Side.ABOVE;
        }

        /** The crossing of edge (a, b), a < b, at the same fraction in 3D and on paper. */
        private int splitEdge(int a, int b) {
            double da = distance(a);
            double db = distance(b);
            double t = da / (da - db);
            return addVertex(
                    xyz[3 * a] + t * (xyz[3 * b] - xyz[3 * a]),
                    xyz[3 * a + 1] + t * (xyz[3 * b + 1] - xyz[3 * a + 1]),
                    xyz[3 * a + 2] + t * (xyz[3 * b + 2] - xyz[3 * a + 2]),
                    uv[2 * a] + t * (uv[2 * b] - uv[2 * a]),
                    uv[2 * a + 1] + t * (uv[2 * b + 1] - uv[2 * a + 1]),
                    Plane.Side.ON);
        }

        /** Adds a paper face, cut in two at its two vertices on the plane if it has vertices on both sides. */
        private void addCutFace(int[] loop, boolean cap) {
            boolean above = false;
            boolean below = false;
            for (int v : loop) {
                above |= sides[v] == Plane.Side.ABOVE;
                below |= sides[v] == Plane.Side.BELOW;
            }
            anyAbove |= above && !cap;
            anyBelow |= below && !cap;
            if (!(above && below)) {
                faces.add(loop);
                caps.add(cap);
                return;
            }
            // A convex face meets the plane in a segment: its part on each side is its vertices on
            // that side and on the plane, in order. A part left with fewer than three corners (a
            // cap so thin that more of its corners lie on the plane) is no face and is dropped.
            for (Plane.Side away : new Plane.Side[] {Plane.Side.BELOW, Plane.Side.ABOVE}) {
                int[] part = new int[loop.length];
                int size = 0;
                for (int v : loop) {
                    if (sides[v] != away) {
                        part[size++] = v;
                    }
                }
                if (size >= 3) {
                    faces.add(Arrays.copyOf(part, size));
                    caps.add(cap);
                }
            }
        }

        private boolean isMoving(int[] face) {
            for (int v : face) {
                if (sides[v] == Plane.Side.ABOVE) {
                    return true;
                }
            }
            return false;
        }

        /**
         * Places a flap fold's crease in space: through the crease points of the moving faces,
         * the two farthest apart on paper giving the line, and towards the moving side as the
         * faces beside the crease show it.
         */
        Prepared assembleFlap(FlapFold fold) throws FoldException {
            int first = -1;
            int second = -1;
            double widest = -1;
            List<Integer> onCrease = new ArrayList<>();
            int beyond = -1;
            for (int f = 0; f < faces.size(); f++) {
                if (caps.get(f) || !isMoving(faces.get(f))) {
                    continue;
                }
                boolean touches = false;
                for (int v : faces.get(f)) {
                    if (sides[v] == Plane.Side.ON) {
                        onCrease.add(v);
                        touches = true;
                    }
                }
                if (touches && beyond < 0) {
                    for (int v : faces.get(f)) {
                        if (sides[v] == Plane.Side.ABOVE) {
                            beyond = v;
                        }
                    }
                }
            }
            for (int i = 0; i < onCrease.size(); i++) {
                for (int j = i + 1; j < onCrease.size(); j++) {
                    int a = onCrease.get(i);
                    int b = onCrease.get(j);
                    double d = Math.hypot(uv[2 * a] - uv[2 * b], uv[2 * a + 1] - uv[2 * b + 1]);
                    if (d > widest) {
                        widest = d;
                        first = a;
                        second = b;
                    }
                }
            }
            if (first < 0 || beyond < 0) {
                throw new FoldException("the crease does not cross the flap: it only touches the paper");
            }
            Vector3d point = position(first);
            Vector3d direction = position(second).sub(point);
            Vector3dc n = paper.normal;
            direction.fma(-direction.dot(n), n);
            if (!(direction.length() > tolerance)) {
                throw new FoldException("the crease stands across the paper: the flap must lie flat where it is folded");
            }
            direction.normalize();
            for (int v : onCrease) {
                Vector3d offset = position(v).sub(point);
                offset.fma(-offset.dot(direction), direction);
                if (offset.length() > 1e3 * tolerance) {
                    throw new FoldException("the crease crosses paper that is already folded: it is not one straight line in space");
                }
            }
            Vector3d side = position(beyond).sub(point);
            side.fma(-side.dot(direction), direction).fma(-side.dot(n), n);
            if (!(side.length() > tolerance)) {
                throw new FoldException("the flap stands across the paper: it must lie flat where it is folded");
            }
            side.normalize();
            return assemble(fold.kind(), fold.angleDegrees(), point, side);
        }

        private Vector3d position(int v) {
            return new Vector3d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
        }

        Prepared assemble(Fold.Kind kind, double angleDegrees, Vector3dc linePoint, Vector3dc side) {
            int faceCount = faces.size();
            boolean[] moving = new boolean[faceCount];
            boolean[] usedByMoving = new boolean[vertexCount];
            boolean[] usedByMovingPaper = new boolean[vertexCount];
            boolean[] usedByFixed = new boolean[vertexCount];
            java.util.Set<Long> fixedEdges = new java.util.HashSet<>();
            boolean[] usedByFixedPaper = new boolean[vertexCount];
            for (int f = 0; f < faceCount; f++) {
                if (!caps.get(f)) {
                    moving[f] = isMoving(faces.get(f));
                    for (int v : faces.get(f)) {
                        usedByMovingPaper[v] |= moving[f];
                        usedByFixedPaper[v] |= !moving[f];
                    }
                }
            }
            for (int f = 0; f < faceCount; f++) {
                if (caps.get(f)) {
                    moving[f] = capMoves(faces.get(f), usedByMovingPaper, usedByFixedPaper);
                }
            }
            for (int f = 0; f < faceCount; f++) {
                int[] face = faces.get(f);
                for (int i = 0; i < face.length; i++) {
                    int v = face[i];
                    if (moving[f]) {
                        usedByMoving[v] = true;
                    } else {
                        usedByFixed[v] = true;
                        fixedEdges.add(((long) v << 32) | face[(i + 1) % face.length]);
                    }
                }
            }
            // The axis: a 180-degree turn about it maps height z to 2h - z, reversing the order of
            // the moving layers; it must put the moving layer that is highest at the line one
            // thickness above the highest layer that stays there (valley), or the lowest one below
            // the lowest (mountain).
            Vector3dc n = paper.normal;
            double[] fixedRange = {Double.NaN, Double.NaN};
            double[] movingRange = {Double.NaN, Double.NaN};
            for (int f = 0; f < faceCount; f++) {
                if (caps.get(f)) {
                    continue;
                }
                for (int v : faces.get(f)) {
                    if (sides[v] == Plane.Side.ON) {
                        double h = n.x() * xyz[3 * v] + n.y() * xyz[3 * v + 1] + n.z() * xyz[3 * v + 2];
                        include(moving[f] ? movingRange : fixedRange, h);
                    }
                }
            }
            double lineHeight = linePoint.dot(n);
            if (Double.isNaN(fixedRange[0])) {
                fixedRange = Double.isNaN(movingRange[0]) ? new double[] {lineHeight, lineHeight} : movingRange;
            }
            if (Double.isNaN(movingRange[0])) {
                movingRange = fixedRange;
            }
            double t = paper.thickness;
            boolean valley = kind == Fold.Kind.VALLEY;
            double axisHeight = valley ? (fixedRange[1] + movingRange[1] + t) / 2 : (fixedRange[0] + movingRange[0] - t) / 2;
            if (angleDegrees == 180) { // only a flat fold lands: a partial one turns about the line's layers
                axisHeight = Landing.axisHeight(this.paperView(moving), linePoint, side, n, valley, t, axisHeight);
            }
            Vector3d axisPoint = new Vector3d(linePoint).fma(axisHeight - linePoint.dot(n), n);
            // Valley: the moving side turns up towards n, so the axis is side × n; mountain: n × side.
            Vector3d axis = valley ? new Vector3d(side).cross(n) : new Vector3d(n).cross(side);
            axis.normalize();

            // Clone the fold-line vertices that moving faces share with faces that stay.
            int originalVertices = vertexCount;
            int[] clone = new int[originalVertices];
            int[] halfClone = new int[originalVertices];
            Arrays.fill(clone, -1);
            Arrays.fill(halfClone, -1);
            boolean gap = t > 0;
            if (gap) {
                for (int v = 0; v < originalVertices; v++) {
                    if (sides[v] == Plane.Side.ON && usedByMoving[v] && usedByFixed[v]) {
                        clone[v] = copyVertex(v);
                        halfClone[v] = copyVertex(v);
                    }
                }
            }
            List<int[]> result = new ArrayList<>(faceCount + 16);
            List<Boolean> resultCaps = new ArrayList<>(faceCount + 16);
            boolean[] turns = new boolean[vertexCount];
            for (int f = 0; f < faceCount; f++) {
                int[] face = faces.get(f);
                if (moving[f]) {
                    int[] moved = face.clone();
                    for (int i = 0; i < moved.length; i++) {
                        if (clone[moved[i]] >= 0) {
                            moved[i] = clone[moved[i]];
                        }
                        turns[moved[i]] = true;
                    }
                    // Each fold-line edge a -> b of a moving face becomes the cap's far side.
                    for (int i = 0; i < face.length; i++) {
                        int a = face[i];
                        int b = face[(i + 1) % face.length];
                        // The face that stays across the line has b -> a; the cap's first facet
                        // takes a -> b from it, the second hands b' -> a' to the moved face.
                        if (gap && clone[a] >= 0 && clone[b] >= 0 && fixedEdges.contains(((long) b << 32) | a)) {
                            result.add(new int[] {a, b, halfClone[b], halfClone[a]});
                            resultCaps.add(true);
                            result.add(new int[] {halfClone[a], halfClone[b], clone[b], clone[a]});
                            resultCaps.add(true);
                        }
                    }
                    result.add(moved);
                } else {
                    result.add(face);
                }
                resultCaps.add(caps.get(f));
            }
            // Creases: the fold-line edges, as the layer that stays sees them.
            for (int f = 0; f < faceCount; f++) {
                if (moving[f]) {
                    continue;
                }
                int[] face = faces.get(f);
                for (int i = 0; i < face.length; i++) {
                    int a = face[i];
                    int b = face[(i + 1) % face.length];
                    if (sides[a] == Plane.Side.ON && sides[b] == Plane.Side.ON && usedByMoving[a] && usedByMoving[b]) {
                        creases.add(new long[] {Math.min(a, b), Math.max(a, b)});
                    }
                }
            }
            boolean[] halfTurns = new boolean[vertexCount];
            for (int v : halfClone) {
                if (v >= 0) {
                    halfTurns[v] = true;
                }
            }
            int before = vertexCount;
            splitPinchedVertices(result);
            turns = Arrays.copyOf(turns, vertexCount);
            halfTurns = Arrays.copyOf(halfTurns, vertexCount);
            for (int v = before; v < vertexCount; v++) {
                turns[v] = turns[copiedFrom.get(v - before)];
                halfTurns[v] = halfTurns[copiedFrom.get(v - before)];
            }
            int[] movingVertices = indicesOf(turns, vertexCount);
            int[] halfVertices = indicesOf(halfTurns, vertexCount);
            boolean[] capArray = new boolean[result.size()];
            for (int f = 0; f < capArray.length; f++) {
                capArray[f] = resultCaps.get(f);
            }
            Paper cut = new Paper(Arrays.copyOf(xyz, 3 * vertexCount), Arrays.copyOf(uv, 2 * vertexCount), result, capArray,
                    t, n, distinct(creases));
            return new Prepared(cut, movingVertices, halfVertices, axisPoint, axis, Math.toRadians(angleDegrees));
        }

        /** For each vertex made by {@link #splitPinchedVertices}, the vertex it copies. */
        private final List<Integer> copiedFrom = new ArrayList<>();

        /**
         * Gives each fan of faces around a vertex its own vertex. A fold separates the faces
         * around a fold-line vertex into those that move and those that stay; where a vertex
         * joined layers that meet only there (the corner where two earlier creases meet, lying
         * on the new line), the faces left around one copy may form two fans touching at a point,
         * which paper cannot do. Each extra fan gets a copy of the vertex, at the same place and
         * moving as the vertex moves.
         */
        private void splitPinchedVertices(List<int[]> faces) {
            int[] cornerCount = new int[vertexCount];
            for (int[] face : faces) {
                for (int v : face) {
                    cornerCount[v]++;
                }
            }
            int[] firstCorner = new int[vertexCount + 1];
            for (int v = 0; v < vertexCount; v++) {
                firstCorner[v + 1] = firstCorner[v] + cornerCount[v];
            }
            int[] cornerFace = new int[firstCorner[vertexCount]];
            int[] cornerIndex = new int[firstCorner[vertexCount]];
            int[] fill = Arrays.copyOf(firstCorner, vertexCount);
            for (int f = 0; f < faces.size(); f++) {
                int[] face = faces.get(f);
                for (int i = 0; i < face.length; i++) {
                    int slot = fill[face[i]]++;
                    cornerFace[slot] = f;
                    cornerIndex[slot] = i;
                }
            }
            int vertices = vertexCount;
            for (int v = 0; v < vertices; v++) {
                int from = firstCorner[v];
                int count = firstCorner[v + 1] - from;
                if (count < 2) {
                    continue;
                }
                // Corners around v are joined when their faces share an edge at v (the same
                // neighbour). Fans are small: compare every two corners.
                int[] parent = new int[count];
                int[] next = new int[count];
                int[] previous = new int[count];
                for (int c = 0; c < count; c++) {
                    parent[c] = c;
                    int[] face = faces.get(cornerFace[from + c]);
                    int i = cornerIndex[from + c];
                    next[c] = face[(i + 1) % face.length];
                    previous[c] = face[(i + face.length - 1) % face.length];
                }
                boolean pinched = false;
                for (int c = 1; c < count; c++) {
                    for (int d = 0; d < c; d++) {
                        if (next[c] == next[d] || next[c] == previous[d] || previous[c] == next[d] || previous[c] == previous[d]) {
                            parent[root(parent, c)] = root(parent, d);
                        }
                    }
                }
                for (int c = 1; c < count; c++) {
                    pinched |= root(parent, c) != root(parent, 0);
                }
                if (!pinched) {
                    continue;
                }
                Map<Integer, Integer> copyOfFan = new HashMap<>();
                for (int c = 0; c < count; c++) {
                    int fan = root(parent, c);
                    if (fan == root(parent, 0)) {
                        continue; // the first fan keeps the vertex
                    }
                    Integer copy = copyOfFan.get(fan);
                    if (copy == null) {
                        copy = copyVertex(v);
                        copiedFrom.add(v);
                        copyOfFan.put(fan, copy);
                    }
                    faces.get(cornerFace[from + c])[cornerIndex[from + c]] = copy;
                }
            }
        }

        private static int root(int[] parent, int i) {
            while (parent[i] != i) {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            return i;
        }

        /** The cut faces as they stand now, with which of them move: what {@link Landing} needs. */
        private Landing.Faces paperView(boolean[] moving) {
            return new Landing.Faces(xyz, faces, caps, moving, tolerance);
        }

        /**
         * A cap goes with the layers it joins, not with the side of the plane it pokes into
         * (caps stick out half a thickness beyond their crease): it moves if it joins paper that
         * moves, and stays if it joins paper that stays (also when it joins both: the new fold
         * runs along its crease). A cap that touches paper only on the fold line goes by which
         * side of the plane it lies on.
         */
        private boolean capMoves(int[] cap, boolean[] usedByMovingPaper, boolean[] usedByFixedPaper) {
            boolean joinsMoving = false;
            boolean above = false;
            for (int v : cap) {
                if (usedByFixedPaper[v] && !usedByMovingPaper[v]) {
                    return false;
                }
                joinsMoving |= usedByMovingPaper[v] && !usedByFixedPaper[v];
                above |= sides[v] == Plane.Side.ABOVE;
            }
            return joinsMoving || above;
        }

        private static void include(double[] range, double h) {
            range[0] = Double.isNaN(range[0]) ? h : Math.min(range[0], h);
            range[1] = Double.isNaN(range[1]) ? h : Math.max(range[1], h);
        }

        private static int[] indicesOf(boolean[] flags, int count) {
            int[] indices = new int[count];
            int n = 0;
            for (int i = 0; i < count; i++) {
                if (flags[i]) {
                    indices[n++] = i;
                }
            }
            return Arrays.copyOf(indices, n);
        }

        private static List<long[]> distinct(List<long[]> edges) {
            Map<Long, long[]> unique = new java.util.LinkedHashMap<>();
            for (long[] edge : edges) {
                unique.putIfAbsent((edge[0] << 32) | edge[1], edge);
            }
            return new ArrayList<>(unique.values());
        }
    }
}
