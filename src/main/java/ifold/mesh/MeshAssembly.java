package ifold.mesh;

import java.util.Arrays;
import java.util.Map;

/**
 * Steps 5 to 7 of {@link MeshBuilder}: the halfedges paired across the edges (a non-manifold
 * edge split into manifold pairs), the fans of a pinched vertex split apart, the boundaries
 * linked, and the halfedge mesh assembled from them.
 */
final class MeshAssembly {
    private final MeshBuilder builder;

    MeshAssembly(MeshBuilder builder) {
        this.builder = builder;
    }

    /**
     * Pairs each edge's halfedges and numbers the halfedges: returns the halfedge of each
     * corner. Paired corners share an edge (halfedges 2e and 2e + 1); a corner left unpaired
     * gets an edge of its own whose twin is a boundary halfedge.
     */
    int[] pairHalfedges() throws InvalidMeshException {
        // First pass: the partner of each corner, encoded as -(partner + 2); -1 for none.
        int[] cornerHalfedge = new int[builder.wCornerCount];
        Arrays.fill(cornerHalfedge, -1);
        for (int c = 0; c < builder.wCornerCount; c++) {
            int d = builder.mate[c];
            // Orientation made the mates run in opposite directions, unless the edge lies twice
            // in one face: such corners stay boundary.
            if (d > c && builder.cornerFrom(c) != builder.cornerFrom(d) && builder.faceOfCorner(c) != builder.faceOfCorner(d)) {
                cornerHalfedge[c] = -(d + 2);
                cornerHalfedge[d] = -(c + 2);
            }
        }
        if (builder.byMin != null) {
            pairNonManifoldEdges(cornerHalfedge);
        }
        // Second pass: number the halfedges in corner order.
        int h = 0;
        for (int c = 0; c < builder.wCornerCount; c++) {
            int partner = cornerHalfedge[c];
            if (partner >= 0) {
                continue; // numbered with its partner
            }
            cornerHalfedge[c] = h;
            if (partner <= -2) {
                cornerHalfedge[-partner - 2] = h + 1;
            }
            h += 2;
        }
        builder.halfedgeCount = h;
        builder.byMin = null;
        builder.mate = null;
        return cornerHalfedge;
    }

    /**
     * Splits each edge that more than two corners share: joins the first two corners of
     * opposite direction in different faces and leaves the rest boundary.
     */
    private void pairNonManifoldEdges(int[] cornerHalfedge) throws InvalidMeshException {
        for (int i = 0; i < builder.byMin.length; ) {
            int first = builder.byMin[i];
            int low = Math.min(builder.cornerFrom(first), builder.cornerTo(first));
            int high = Math.max(builder.cornerFrom(first), builder.cornerTo(first));
            int end = i + 1;
            while (end < builder.byMin.length && Math.min(builder.cornerFrom(builder.byMin[end]), builder.cornerTo(builder.byMin[end])) == low
                    && Math.max(builder.cornerFrom(builder.byMin[end]), builder.cornerTo(builder.byMin[end])) == high) {
                end++;
            }
            if (builder.mate[first] == MeshBuilder.NON_MANIFOLD) {
                int f = builder.wSource[builder.faceOfCorner(first)];
                if (builder.options.strict()) {
                    throw builder.refuse(Defect.NON_MANIFOLD_EDGE, f, "face " + f + ": edge " + builder.cornerFrom(first) + "-"
                            + builder.cornerTo(first) + " is shared by " + (end - i) + " faces");
                }
                builder.repair(Defect.NON_MANIFOLD_EDGE, f, 1);
                search:
                for (int j = i; j < end; j++) {
                    for (int k = j + 1; k < end; k++) {
                        int c = builder.byMin[j];
                        int d = builder.byMin[k];
                        if (builder.cornerFrom(c) != builder.cornerFrom(d) && builder.faceOfCorner(c) != builder.faceOfCorner(d)) {
                            cornerHalfedge[c] = -(d + 2);
                            cornerHalfedge[d] = -(c + 2);
                            break search;
                        }
                    }
                }
            }
            i = end;
        }
    }

    MeshBuilder.Result assemble(int[] cornerHalfedge) throws InvalidMeshException {
        int[] toVertex = new int[builder.halfedgeCount];
        int[] face = new int[builder.halfedgeCount];
        int[] next = new int[builder.halfedgeCount];
        int[] prev = new int[builder.halfedgeCount];
        // Boundary halfedges have no corner: they are the twins not set below, and point back
        // to where their interior twin starts.
        Arrays.fill(face, -1);
        int[] faceHalfedge = new int[builder.wFaceCount];
        for (int f = 0; f < builder.wFaceCount; f++) {
            int start = builder.faceStart(f);
            int end = builder.faceStart(f + 1);
            faceHalfedge[f] = cornerHalfedge[start];
            for (int c = start; c < end; c++) {
                int hc = cornerHalfedge[c];
                int hn = cornerHalfedge[c + 1 < end ? c + 1 : start];
                // The twin ends where this corner starts: a boundary twin gets its vertex only
                // here; an interior twin is written again, the same, from its own corner.
                toVertex[hc ^ 1] = builder.wVerts[c];
                toVertex[hc] = builder.wVerts[c + 1 < end ? c + 1 : start];
                face[hc] = f;
                next[hc] = hn;
                prev[hn] = hc;
            }
        }
        cornerHalfedge = null; // as big as a halfedge array: let it go before the next ones

        // Vertices: referenced input vertices keep their order; pinch splits come after.
        int inputVertices = builder.soup.vertexCount();
        int[] meshVertex = new int[inputVertices];
        Arrays.fill(meshVertex, -1);
        int vertexCount = 0;
        for (int c = 0; c < builder.wCornerCount; c++) {
            meshVertex[builder.wVerts[c]] = 0;
        }
        int unreferenced = 0;
        int firstUnreferenced = -1;
        for (int v = 0; v < inputVertices; v++) {
            if (meshVertex[v] == 0) {
                meshVertex[v] = vertexCount++;
            } else {
                unreferenced++;
                if (firstUnreferenced < 0) {
                    firstUnreferenced = v;
                }
            }
        }
        if (unreferenced > 0) {
            if (builder.options.strict()) {
                throw new InvalidMeshException(Defect.UNREFERENCED_VERTEX, 0,
                        "vertex " + firstUnreferenced + ": " + Defect.UNREFERENCED_VERTEX.description());
            }
            builder.repairs.merge(Defect.UNREFERENCED_VERTEX, unreferenced, Integer::sum);
        }
        if (unreferenced > 0) { // otherwise every vertex keeps its number
            for (int i = 0; i < builder.halfedgeCount; i++) {
                toVertex[i] = meshVertex[toVertex[i]];
            }
        }
        int[] sourceVertex = new int[Math.max(4, vertexCount + vertexCount / 8)];
        for (int v = 0; v < inputVertices; v++) {
            if (meshVertex[v] >= 0) {
                sourceVertex[meshVertex[v]] = v;
            }
        }

        // Split pinches: walk each fan of faces around a vertex once; a vertex already claimed
        // by an earlier fan gets a copy for this one.
        int[] vertexHalfedge = new int[sourceVertex.length];
        Arrays.fill(vertexHalfedge, -1);
        boolean[] visited = new boolean[builder.halfedgeCount];
        boolean[] pinched = new boolean[vertexCount];
        int pinchCount = 0;
        for (int start = 0; start < builder.halfedgeCount; start++) {
            if (face[start] < 0 || visited[start]) {
                continue;
            }
            // Counter-clockwise from start to the boundary, or all the way round; an open fan
            // is then walked clockwise from start to its other end.
            int boundaryOut = -1;
            int h = start;
            while (true) {
                visited[h] = true;
                int ccw = prev[h] ^ 1;
                if (face[ccw] < 0) {
                    boundaryOut = ccw; // the boundary halfedge leaving this fan
                    break;
                }
                if (ccw == start) {
                    break;
                }
                h = ccw;
            }
            if (boundaryOut >= 0) {
                for (h = start; face[h ^ 1] >= 0; ) {
                    h = next[h ^ 1];
                    visited[h] = true;
                }
            }
            int v = toVertex[prev[start]];
            if (vertexHalfedge[v] >= 0) {
                if (builder.options.strict()) {
                    throw new InvalidMeshException(Defect.NON_MANIFOLD_VERTEX, 0, "vertex "
                            + sourceVertex[v] + ": " + Defect.NON_MANIFOLD_VERTEX.description());
                }
                if (!pinched[v]) {
                    pinched[v] = true;
                    pinchCount++;
                }
                if (vertexCount == sourceVertex.length) {
                    sourceVertex = Arrays.copyOf(sourceVertex, 2 * vertexCount);
                    vertexHalfedge = Arrays.copyOf(vertexHalfedge, 2 * vertexCount);
                }
                sourceVertex[vertexCount] = sourceVertex[v];
                v = vertexCount++;
                moveFan(start, v, toVertex, next, prev, face);
            }
            // A closed fan starts one step counter-clockwise of where the walk began.
            vertexHalfedge[v] = boundaryOut >= 0 ? boundaryOut : prev[start] ^ 1;
        }
        if (pinchCount > 0) {
            builder.repairs.merge(Defect.NON_MANIFOLD_VERTEX, pinchCount, Integer::sum);
        }

        // Boundary loops: each vertex now has at most one boundary halfedge leaving it.
        for (int b = 0; b < builder.halfedgeCount; b++) {
            if (face[b] < 0) {
                int out = vertexHalfedge[toVertex[b]];
                next[b] = out;
                prev[out] = b;
            }
        }

        double[] positions = new double[3 * sourceVertex.length];
        for (int v = 0; v < vertexCount; v++) {
            System.arraycopy(builder.xyz, 3 * sourceVertex[v], positions, 3 * v, 3);
        }
        int[] faceColor = null;
        if (builder.soup.hasFaceColors()) {
            faceColor = new int[builder.wFaceCount];
            for (int f = 0; f < builder.wFaceCount; f++) {
                faceColor[f] = builder.soup.faceColor(builder.wSource[f]);
            }
        }
        HalfedgeMesh mesh = HalfedgeMesh.adopt(positions, vertexHalfedge, vertexCount, next, prev, toVertex,
                face, builder.halfedgeCount, faceHalfedge, faceColor, builder.wFaceCount);
        int[] sourceFace = Arrays.copyOf(builder.wSource, builder.wFaceCount);
        return new MeshBuilder.Result(mesh, Map.copyOf(builder.repairs), sourceFace, Arrays.copyOf(sourceVertex, vertexCount));
    }

    /**
     * Points the fan of halfedge {@code start} (its outgoing halfedges, and the incoming ones
     * before them and across from them) at vertex {@code v}, the copy made for a pinch.
     */
    private static void moveFan(int start, int v, int[] toVertex, int[] next, int[] prev, int[] face) {
        int h = start;
        while (true) {
            toVertex[prev[h]] = v;
            toVertex[h ^ 1] = v;
            int ccw = prev[h] ^ 1;
            if (ccw == start) {
                return; // closed: all of it done
            }
            if (face[ccw] < 0) {
                break;
            }
            h = ccw;
        }
        for (h = start; face[h ^ 1] >= 0; ) {
            h = next[h ^ 1];
            toVertex[prev[h]] = v;
            toVertex[h ^ 1] = v;
        }
    }
}
