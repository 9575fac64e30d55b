package ifold.scene;

import ifold.geom.IntList;
import ifold.mesh.IndexedPolygons;
import ifold.sheet.HostFrame;
import ifold.wrap.CoveredPaper;
import ifold.wrap.Wrap;
import ifold.wrap.PaperInSpace;
import java.util.BitSet;
import java.util.List;
import org.joml.Vector3d;

/**
 * A wrap on screen: the model, solid in a quiet colour, and the strips laid over it face by
 * face in the order they were folded, the camera following the triangle being wrapped; at the
 * end the camera turns once around the wrapped model. The strips are one mesh whose triangles
 * come in the order their faces were made, so that showing the wrap up to a moment is showing
 * a prefix of it: nothing is rebuilt per frame.
 */
public final class WrapView {
    public static final int MODEL = 0xFF7D8A99;
    static final int REVEAL_STEPS = 4 * 360;
    static final int TURN_STEPS = 360;
    /** The part of the final turn over which the camera glides from the last fold's view. */
    static final double GLIDE = 0.12;

    WrapView() {
    }

    /** How the paper is drawn: its top side cream, caps grey, its underside blue-grey; no outlines (the faces are many and small). */
    public static final Material PAPER = new Material(PaperView.PAPER, 0xFF8FAACB, true, false);

    /**
     * The paper of the triangle being wrapped: its faces outlined, so that each pass, turn and
     * tucked flap can be told from the next while it is made.
     */
    public static final Material PAPER_FOLDING = new Material(PaperView.PAPER, 0xFF8FAACB, true, true);

    /** The legend's lines for the paper: its two sides in the colours it is drawn in. */
    public static final Scene.Swatch TOP_SIDE = new Scene.Swatch(PaperView.PAPER, "paper, top side");
    public static final Scene.Swatch UNDERSIDE = new Scene.Swatch(PAPER.back(), "paper, underside");

    /** The outline of a face being folded: darker than the paper, quieter than the model's edges. */
    static final int FACE_EDGE = 0xFF6F7B88;

    /** The wrap's strips and, for each strip and path triangle, how many of the mesh's triangles exist once it is wrapped. */
    /**
     * The strips' paper drawn as one mesh, the triangles of it laid by the end of each path
     * triangle of each strip, and the paper in space it was drawn from (a face as it finally
     * lies, crept back from concave edges as thick layers must be).
     */
    public record Strips(SceneMesh mesh, int[][] trianglesAfter, List<PaperInSpace> geometries) {
    }

    /**
     * Whether paper on {@code mesh} can be seen from below its faces too: an open surface (an
     * edge with one face: the zig-zag demo's lone triangle, the turn gadget's table), or no
     * surface at all. A closed solid hides what lies under its paper. Asked once a wrap drawn.
     */
    static boolean seenFromBothSides(IndexedPolygons mesh) {
        if (mesh == null || mesh.faceCount() == 0) {
            return true;
        }
        java.util.Map<Long, Integer> uses = new java.util.HashMap<>();
        for (int f = 0; f < mesh.faceCount(); f++) {
            int n = mesh.faceSize(f);
            for (int k = 0; k < n; k++) {
                long a = mesh.faceVertex(f, k);
                long b = mesh.faceVertex(f, (k + 1) % n);
                uses.merge(Math.min(a, b) << 32 | Math.max(a, b), 1, Integer::sum);
            }
        }
        for (int count : uses.values()) {
            if (count == 1) {
                return true;
            }
        }
        return false;
    }

    public static Strips strips(Wrap.Result result, List<PaperInSpace> geometries) {
        int total = 0;
        for (PaperInSpace g : geometries) {
            total += g.vertexCount();
        }
        double[] positions = new double[3 * total];
        // Corners three a triangle, and colours, in lists of blocks: a wrap of a million faces
        // draws several million triangles, an array and a boxed colour each before.
        IntList triangles = new IntList();
        IntList colors = new IntList();
        IntList hiddenFrom = new IntList();
        BitSet seams = new BitSet();
        IntList patchOf = new IntList();
        HostPatches patches = new HostPatches(result);
        boolean bothSides = seenFromBothSides(result.mesh());
        int[][] after = new int[geometries.size()][];
        int base = 0;
        for (int k = 0; k < geometries.size(); k++) {
            PaperInSpace g = geometries.get(k);
            Wrap.Strip strip = result.strips().get(k);
            System.arraycopy(g.xyz(), 0, positions, 3 * base, 3 * g.vertexCount());
            // Caps come right after the later of the faces they join, in the order made: the caps
            // after face f are capsAfter[capsStart[f]] to capsAfter[capsStart[f + 1] - 1].
            int faceCount = g.paperFaces().size();
            int[] capsStart = new int[faceCount + 1];
            for (int c = 0; c < g.caps().size(); c++) {
                capsStart[g.capAfter()[c] + 1]++;
            }
            for (int f = 0; f < faceCount; f++) {
                capsStart[f + 1] += capsStart[f];
            }
            int[] capsAfter = new int[g.caps().size()];
            int[] filled = java.util.Arrays.copyOf(capsStart, faceCount);
            for (int c = 0; c < g.caps().size(); c++) {
                capsAfter[filled[g.capAfter()[c]]++] = c;
            }
            // What lies under other paper is not drawn once that paper is there.
            CoveredPaper.Covered covered = CoveredPaper.of(g, result.frames(), strip.sheet().thickness(), bothSides);
            int[] levels = strip.sheet().levels();
            int[] trianglesAtFace = new int[faceCount + 1];
            for (int f = 0; f < faceCount; f++) {
                trianglesAtFace[f] = colors.size();
                int from = colors.size();
                int host = g.paperHosts()[f];
                fan(g.paperFaces().get(f), base, PaperView.PAPER, triangles, colors);
                hiddenFrom.add(covered.faceCover()[f], colors.size() - from); // the face that covers it, for now
                if (!covered.face(f)) {
                    patches.add(host, covered.undersideOut().get(f) ? PAPER.back() : PAPER.front(), covered.areas()[f]);
                }
                patches.layer(host, (levels[g.sheetFace(f)] + 0.5) * strip.sheet().thickness(), colors.size());
                patchOf.add(host, colors.size() - from);
                for (int at = capsStart[f]; at < capsStart[f + 1]; at++) {
                    int c = capsAfter[at];
                    from = colors.size();
                    fan(g.caps().get(c), base, PaperView.CAP, triangles, colors);
                    seams.set(from, colors.size());
                    hiddenFrom.add(covered.capCover()[c], colors.size() - from);
                    patchOf.add(host, colors.size() - from);
                    patches.layer(host, Double.NEGATIVE_INFINITY, colors.size());
                }
            }
            trianglesAtFace[faceCount] = colors.size();
            // Covered once the face that covers it is drawn whole.
            for (int t = trianglesAtFace[0]; t < colors.size(); t++) {
                int cover = hiddenFrom.get(t);
                hiddenFrom.set(t, cover < 0 ? Integer.MAX_VALUE : trianglesAtFace[cover + 1]);
            }
            after[k] = new int[strip.triangles()];
            for (int i = 0; i < strip.triangles(); i++) {
                after[k][i] = trianglesAtFace[g.pieceStart()[strip.facesAfter()[i]]];
            }
            base += g.vertexCount();
        }
        int[] flat = triangles.toArray();
        int[] colorArray = colors.toArray();
        SceneMesh.Layers layers = patches.layers(hiddenFrom.toArray(), seams, patchOf.toArray());
        return new Strips(new SceneMesh(positions, flat, colorArray, new int[0], new int[0], layers), after, List.copyOf(geometries));
    }

    /**
     * What the paper on each host looks like from far away: the host's triangles of the model,
     * raised to the paper's top layer, in the colours of the paper exposed there averaged by
     * area (its top side and its underside). A host is settled once its last face and cap are
     * there: what covers what on it holds from then on.
     */
    static final class HostPatches {
        private final Wrap.Result result;
        private final double[] red;
        private final double[] green;
        private final double[] blue;
        private final double[] area;
        private final double[] top;
        private final int[] settled;

        HostPatches(Wrap.Result result) {
            this.result = result;
            int hosts = result.frames().length;
            red = new double[hosts];
            green = new double[hosts];
            blue = new double[hosts];
            area = new double[hosts];
            top = new double[hosts];
            java.util.Arrays.fill(top, Double.NEGATIVE_INFINITY);
            settled = new int[hosts];
        }

        void add(int host, int argb, double faceArea) {
            red[host] += faceArea * (argb >> 16 & 0xFF);
            green[host] += faceArea * (argb >> 8 & 0xFF);
            blue[host] += faceArea * (argb & 0xFF);
            area[host] += faceArea;
        }

        /** Paper at {@code height} on {@code host}, its triangles ending at {@code end}. */
        void layer(int host, double height, int end) {
            top[host] = Math.max(top[host], height);
            settled[host] = Math.max(settled[host], end);
        }

        SceneMesh.Layers layers(int[] hiddenFrom, BitSet seams, int[] patchOf) {
            IndexedPolygons mesh = result.mesh();
            int hosts = settled.length;
            int[] start = new int[hosts + 1];
            for (int t = 0; t < mesh.faceCount(); t++) {
                start[result.hostOf()[t] + 1] += area[result.hostOf()[t]] > 0 ? 1 : 0;
            }
            for (int h = 0; h < hosts; h++) {
                start[h + 1] += start[h];
            }
            int count = start[hosts];
            // Neighbour patches share their corners, raised along the mean of their hosts'
            // normals to the highest of their tops: raised each along its own, they would part at
            // every convex edge, the model showing through.
            double[] raise = new double[mesh.vertexCount()];
            double[] normals = new double[3 * mesh.vertexCount()];
            for (int t = 0; t < mesh.faceCount(); t++) {
                int h = result.hostOf()[t];
                if (!(area[h] > 0)) {
                    continue;
                }
                for (int corner = 0; corner < 3; corner++) {
                    int v = mesh.faceVertex(t, corner);
                    raise[v] = Math.max(raise[v], top[h]);
                    for (int axis = 0; axis < 3; axis++) {
                        normals[3 * v + axis] += result.frames()[h].normal()[axis];
                    }
                }
            }
            double[] xyz = new double[3 * mesh.vertexCount()];
            for (int v = 0; v < mesh.vertexCount(); v++) {
                double length = Math.sqrt(normals[3 * v] * normals[3 * v] + normals[3 * v + 1] * normals[3 * v + 1]
                        + normals[3 * v + 2] * normals[3 * v + 2]);
                for (int axis = 0; axis < 3; axis++) {
                    xyz[3 * v + axis] = mesh.coordinate(v, axis) + (length > 0 ? raise[v] * normals[3 * v + axis] / length : 0);
                }
            }
            int[] triangles = new int[3 * count];
            int[] colors = new int[count];
            int[] fill = java.util.Arrays.copyOf(start, hosts);
            for (int t = 0; t < mesh.faceCount(); t++) {
                int h = result.hostOf()[t];
                if (!(area[h] > 0)) {
                    continue; // no paper seen there
                }
                int k = fill[h]++;
                for (int corner = 0; corner < 3; corner++) {
                    triangles[3 * k + corner] = mesh.faceVertex(t, corner);
                }
                colors[k] = 0xFF000000 | (int) Math.round(red[h] / area[h]) << 16 | (int) Math.round(green[h] / area[h]) << 8
                        | (int) Math.round(blue[h] / area[h]);
            }
            SceneMesh patches = new SceneMesh(xyz, triangles, colors, new int[0], new int[0]);
            return new SceneMesh.Layers(hiddenFrom, seams, patchOf, settled, patches, start);
        }
    }

    /** Face's triangles (a fan: faces are convex), three corners each onto {@code triangles}, and a colour each. */
    static void fan(int[] face, int base, int color, IntList triangles, IntList colors) {
        for (int i = 1; i + 1 < face.length; i++) {
            triangles.add(base + face[0]);
            triangles.add(base + face[i]);
            triangles.add(base + face[i + 1]);
            colors.add(color);
        }
    }

    /**
     * The animation, four fifths of its length the wrap and the last fifth a turn around the
     * wrapped model. The wrap plays its folds in order: the tail swinging about each new crease
     * (over or under the paper it lands on, or over the edge onto the next triangle), and the
     * tucks turning the excess under along the triangle's edges, the camera following the
     * triangle being wrapped. Triangles already wrapped are a prefix of {@code done}; the one
     * being wrapped, as it stands at the fold shown, and the swinging paper are drawn by
     * {@code current}, rebuilt for each frame (it is a few dozen faces).
     */
    public static WrapPlayback animation(Scene scene, Geometry done, Geometry current, Strips strips, Wrap.Result result) {
        return new WrapPlayback(scene, done, current, strips, result, null);
    }

    /**
     * Adds the wrap's paper to the scene (what the scene holds already, the model or a
     * triangle, stays under it), frames the whole, and returns its playback, whose last caption
     * counts the strips and triangles wrapped.
     */
    public static WrapPlayback play(Scene scene, Wrap.Result result, List<PaperInSpace> geometries) {
        return play(scene, result, geometries, null);
    }

    /** As {@link #play(Scene, Wrap.Result, List)}, with {@code ending} the caption once all is folded (null for the count). */
    public static WrapPlayback play(Scene scene, Wrap.Result result, List<PaperInSpace> geometries, String ending) {
        Strips strips = strips(result, geometries);
        scene.root().visitGeometry(under -> under.setUnder(true)); // the model, or the triangle, under the paper
        Geometry paper = new Geometry("paper", strips.mesh(), PAPER);
        paper.setHiddenColor(0); // not yet laid: not there
        scene.root().attach(paper);
        Geometry current = new Geometry("folding", strips.mesh(), PAPER_FOLDING);
        scene.root().attach(current);
        scene.frameAll();
        return new WrapPlayback(scene, paper, current, strips, result, ending);
    }

    /** The least time a caption stays on screen: long enough to read a line of it. */
    public static final double CAPTION_SECONDS = 1.5;

    /** The length a playback is paced for until {@link WrapPlayback#pace} says otherwise: a wrap's two minutes. */
    public static final double DEFAULT_SECONDS = 120;

    /** The height of the frame the triangle being wrapped fills, once the camera has come close to it. */
    static final double CLOSE_FILL = 0.5;

    static final SceneMesh EMPTY = new SceneMesh(new double[0], new int[0], new int[0], new int[0], new int[0]);

    static void addPolygon(double[][] corners, int color, List<double[]> points, List<int[]> triangles, List<Integer> colors) {
        int base = points.size();
        for (double[] corner : corners) {
            points.add(corner);
        }
        for (int c = 1; c + 1 < corners.length; c++) {
            triangles.add(new int[] {base, base + c, base + c + 1});
            colors.add(color);
        }
    }

    /** A point turned by {@code angle} about the line through (px, py) with direction (dx, dy) in a triangle's frame, at height 0. */
    static double[] turnAbout(double[] point, HostFrame frame, double px, double py, double dx, double dy, double angle) {
        double[] a = new double[3];
        frame.toSpace(px, py, 0, a, 0);
        double[] b = new double[3];
        frame.toSpace(px + dx, py + dy, 0, b, 0);
        Vector3d axis = new Vector3d(b[0] - a[0], b[1] - a[1], b[2] - a[2]).normalize();
        return rotate(point, new Vector3d(a[0], a[1], a[2]), axis, angle);
    }

    /** Rodrigues: p turned by {@code angle} about the axis through {@code origin}. */
    static double[] rotate(double[] p, Vector3d origin, Vector3d axis, double angle) {
        Vector3d v = new Vector3d(p[0], p[1], p[2]).sub(origin);
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        Vector3d cross = new Vector3d(axis).cross(v);
        double dot = axis.dot(v);
        Vector3d r = new Vector3d(v).mul(c).fma(s, cross).fma(dot * (1 - c), axis).add(origin);
        return new double[] {r.x, r.y, r.z};
    }

}
