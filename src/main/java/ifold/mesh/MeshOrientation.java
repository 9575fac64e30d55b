package ifold.mesh;

import ifold.geom.Tolerance;
import ifold.geom.Triangles;
import java.util.Arrays;

/**
 * Step 4 of {@link MeshBuilder}: every face of a component turned the same way as its
 * neighbours, across each edge two faces share, and each closed component outwards.
 */
final class MeshOrientation {
    private final MeshBuilder builder;

    MeshOrientation(MeshBuilder builder) {
        this.builder = builder;
    }

    boolean[] orient() throws InvalidMeshException {
        boolean[] flip = new boolean[builder.wFaceCount];
        int[] component = new int[builder.wFaceCount];
        Arrays.fill(component, -1);
        // The components one after another, each in the order the walk reached its faces.
        int[] queue = new int[builder.wFaceCount];
        // Per component: turned over as a whole (the minority rule), and closed.
        boolean[] inverted = new boolean[16];
        boolean[] closedComponent = new boolean[16];
        int[] origin = new int[16]; // a vertex of each: volumes are measured from it
        int components = 0;
        int tail = 0;
        for (int seed = 0; seed < builder.wFaceCount; seed++) {
            if (component[seed] >= 0) {
                continue;
            }
            int first = tail;
            int head = tail;
            queue[tail++] = seed;
            component[seed] = components;
            int flipped = 0;
            boolean closed = true;
            while (head < tail) {
                int f = queue[head++];
                for (int c = builder.faceStart(f); c < builder.faceStart(f + 1); c++) {
                    int o = builder.mate[c];
                    if (o < 0) {
                        closed = false;
                        continue;
                    }
                    int of = builder.faceOfCorner(o);
                    if (of == f) {
                        closed = false;
                        continue;
                    }
                    boolean sameDirection = builder.cornerFrom(c) == builder.cornerFrom(o);
                    boolean wanted = flip[f] ^ sameDirection;
                    if (component[of] < 0) {
                        component[of] = components;
                        flip[of] = wanted;
                        if (wanted) {
                            flipped++;
                        }
                        queue[tail++] = of;
                    } else if (flip[of] != wanted) {
                        if (builder.options.strict()) {
                            throw builder.refuse(Defect.NON_ORIENTABLE, builder.wSource[f], "face " + builder.wSource[f]
                                    + ": " + Defect.NON_ORIENTABLE.description());
                        }
                        // Cut the edge: both corners become boundary, so the far side will not
                        // count it again.
                        builder.mate[c] = MeshBuilder.BOUNDARY;
                        builder.mate[o] = MeshBuilder.BOUNDARY;
                        closed = false;
                        builder.repairs.merge(Defect.NON_ORIENTABLE, 1, Integer::sum);
                    }
                }
            }
            int size = tail - first;
            // Turn over the minority: the side most faces agree on is taken as meant.
            boolean invert = 2 * flipped > size;
            int turned = invert ? size - flipped : flipped;
            if (turned > 0) {
                if (builder.options.strict()) {
                    int example = firstDisagreeing(queue, first, tail, flip, invert);
                    throw builder.refuse(Defect.INCONSISTENT_ORIENTATION, builder.wSource[example], "face " + builder.wSource[example]
                            + ": " + Defect.INCONSISTENT_ORIENTATION.description());
                }
                builder.repair(Defect.INCONSISTENT_ORIENTATION, builder.wSource[seed], turned);
            }
            if (components == inverted.length) {
                inverted = Arrays.copyOf(inverted, 2 * components);
                closedComponent = Arrays.copyOf(closedComponent, 2 * components);
                origin = Arrays.copyOf(origin, 2 * components);
            }
            inverted[components] = invert;
            closedComponent[components] = closed;
            origin[components] = builder.wVerts[builder.faceStart(seed)];
            components++;
        }
        // Closed components enclosing a negative volume are turned outward. The volumes are
        // summed in face order, one pass over memory for all components together. A volume
        // next to nothing for its surface's area (a flat closed sheet, a pillow: zero but for
        // rounding, whose sign the order of summing decides) has no inside to turn out.
        double[][] volumes = signedVolumes(component, flip, inverted, closedComponent, origin, components);
        for (int k = 0; k < components; k++) {
            if (closedComponent[k] && volumes[0][k] < -Tolerance.RELATIVE_EQUALITY * Math.pow(volumes[1][k], 1.5)) {
                inverted[k] = !inverted[k];
                builder.repairs.merge(Defect.INWARD_COMPONENT, 1, Integer::sum);
            }
        }
        for (int f = 0; f < builder.wFaceCount; f++) {
            flip[f] ^= inverted[component[f]];
        }
        return flip;
    }

    private static int firstDisagreeing(int[] faces, int from, int to, boolean[] flip, boolean invert) {
        for (int i = from; i < to; i++) {
            if (flip[faces[i]] != invert) {
                return faces[i];
            }
        }
        return faces[from];
    }

    /**
     * Six times the signed volume enclosed by each closed component, with its faces oriented as
     * {@code flip}, then {@code inverted} for the whole component, will orient them, measured
     * from a vertex of its own; and twice its surface's area: {volumes, areas}.
     */
    private double[][] signedVolumes(int[] component, boolean[] flip, boolean[] inverted, boolean[] closed, int[] origin,
            int components) {
        double[] volume = new double[components];
        double[] area = new double[components];
        for (int f = 0; f < builder.wFaceCount; f++) {
            int k = component[f];
            if (!closed[k]) {
                continue;
            }
            int start = builder.faceStart(f);
            int end = builder.faceStart(f + 1);
            int a = builder.wVerts[start];
            double faceVolume = 0;
            for (int c = start + 1; c + 1 < end; c++) {
                faceVolume += tripleProduct(origin[k], a, builder.wVerts[c], builder.wVerts[c + 1]);
                area[k] += Triangles.twiceArea(builder.xyz, a, builder.wVerts[c], builder.wVerts[c + 1]);
            }
            volume[k] += flip[f] ^ inverted[k] ? -faceVolume : faceVolume;
        }
        return new double[][] {volume, area};
    }

    /** The triple product of corners a, b and c taken from vertex o: six times the tetrahedron's signed volume. */
    private double tripleProduct(int o, int a, int b, int c) {
        double ox = builder.xyz[3 * o];
        double oy = builder.xyz[3 * o + 1];
        double oz = builder.xyz[3 * o + 2];
        double ax = builder.xyz[3 * a] - ox;
        double ay = builder.xyz[3 * a + 1] - oy;
        double az = builder.xyz[3 * a + 2] - oz;
        double bx = builder.xyz[3 * b] - ox;
        double by = builder.xyz[3 * b + 1] - oy;
        double bz = builder.xyz[3 * b + 2] - oz;
        double cx = builder.xyz[3 * c] - ox;
        double cy = builder.xyz[3 * c + 1] - oy;
        double cz = builder.xyz[3 * c + 2] - oz;
        return ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
    }

    /**
     * Reverses the vertex lists of flipped faces. Corner k of a reversed face of n corners is
     * the edge that was corner n - 2 - k (and the other way round), so each corner's mate, and
     * its place in {@code byMin}, move with it.
     */
    void reverseFlippedFaces(boolean[] flip) {
        boolean any = false;
        for (int c = 0; c < builder.wCornerCount; c++) {
            if (builder.mate[c] >= 0) {
                builder.mate[c] = reversedIndex(builder.mate[c], flip);
            }
            any |= flip[builder.faceOfCorner(c)];
        }
        if (!any) {
            return;
        }
        if (builder.byMin != null) {
            for (int i = 0; i < builder.byMin.length; i++) {
                builder.byMin[i] = reversedIndex(builder.byMin[i], flip);
            }
        }
        int[] mates = new int[16];
        for (int f = 0; f < builder.wFaceCount; f++) {
            if (!flip[f]) {
                continue;
            }
            int start = builder.faceStart(f);
            int n = builder.faceStart(f + 1) - start;
            if (mates.length < n) {
                mates = new int[2 * n];
            }
            for (int k = 0; k < n; k++) {
                mates[k] = builder.mate[start + Math.floorMod(n - 2 - k, n)];
            }
            System.arraycopy(mates, 0, builder.mate, start, n);
            for (int i = 0, j = n - 1; i < j; i++, j--) {
                int swap = builder.wVerts[start + i];
                builder.wVerts[start + i] = builder.wVerts[start + j];
                builder.wVerts[start + j] = swap;
            }
        }
    }

    /** Where corner {@code c} will be once flipped faces are reversed. */
    private int reversedIndex(int c, boolean[] flip) {
        int f = builder.faceOfCorner(c);
        if (!flip[f]) {
            return c;
        }
        int start = builder.faceStart(f);
        int n = builder.faceStart(f + 1) - start;
        return start + Math.floorMod(n - 2 - (c - start), n);
    }
}
