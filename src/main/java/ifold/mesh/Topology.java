package ifold.mesh;

/**
 * Counts that describe the shape of a mesh as a surface: components (faces joined through
 * shared edges), boundary loops, Euler characteristic and genus.
 *
 * @param vertices vertex count
 * @param edges edge count
 * @param faces face count
 * @param boundaryLoops number of holes
 * @param components connected components through shared edges
 * @param eulerCharacteristic V - E + F
 * @param genus total genus, summed over components: each orientable component with b holes has
 *     Euler characteristic 2 - 2g - b
 */
public record Topology(int vertices, int edges, int faces, int boundaryLoops, int components,
        int eulerCharacteristic, int genus) {

    /** Measures {@code mesh}, which must be valid ({@link MeshValidator}). */
    public static Topology of(HalfedgeMesh mesh) {
        int halfedges = mesh.halfedgeCount();
        boolean[] seen = new boolean[halfedges];
        int loops = 0;
        for (int h = 0; h < halfedges; h++) {
            if (mesh.isBoundary(h) && !seen[h]) {
                loops++;
                int b = h;
                do {
                    seen[b] = true;
                    b = mesh.next(b);
                } while (b != h);
            }
        }
        int[] component = componentOfFaces(mesh);
        int components = 0;
        for (int c : component) {
            components = Math.max(components, c + 1);
        }
        int chi = mesh.vertexCount() - mesh.edgeCount() + mesh.faceCount();
        // Summing 2 - 2g - b over components: total chi = 2c - 2G - B.
        int genus = (2 * components - loops - chi) / 2;
        return new Topology(mesh.vertexCount(), mesh.edgeCount(), mesh.faceCount(), loops, components, chi, genus);
    }

    /**
     * The component of each face: faces are in one component when a chain of shared edges joins
     * them. Components are numbered from 0 in order of their lowest face. Iterative, so a
     * million faces in one strip do not overflow the stack.
     */
    public static int[] componentOfFaces(HalfedgeMesh mesh) {
        int faces = mesh.faceCount();
        int[] component = new int[faces];
        java.util.Arrays.fill(component, -1);
        int[] queue = new int[faces];
        int count = 0;
        for (int seed = 0; seed < faces; seed++) {
            if (component[seed] >= 0) {
                continue;
            }
            int head = 0;
            int tail = 0;
            queue[tail++] = seed;
            component[seed] = count;
            while (head < tail) {
                int f = queue[head++];
                int start = mesh.faceHalfedge(f);
                int h = start;
                do {
                    int g = mesh.face(HalfedgeMesh.twin(h));
                    if (g >= 0 && component[g] < 0) {
                        component[g] = count;
                        queue[tail++] = g;
                    }
                    h = mesh.next(h);
                } while (h != start);
            }
            count++;
        }
        return component;
    }
}
