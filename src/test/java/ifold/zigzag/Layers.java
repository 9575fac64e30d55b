package ifold.zigzag;

import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.fold.Paper;
import ifold.geom.ConvexOverlap;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import org.joml.Matrix4d;
import org.joml.Vector3d;

/** Checks of a flat-folded paper's layers, made face by face in the triangle's plan frame. */
final class Layers {
    private Layers() {
    }

    /** How many distinct heights the paper faces lie at: the stack's depth in layers. */
    static int stackLayers(Paper paper, Matrix4d toPlan) {
        TreeSet<Long> heights = new TreeSet<>();
        double quantum = Math.max(paper.thickness(), 1e-9) / 100;
        for (Face face : faces(paper, toPlan)) {
            heights.add(Math.round(face.height / quantum));
        }
        return heights.size();
    }

    /**
     * No two overlapping faces lie closer than a thickness (nothing passes through anything),
     * every face is flat, and the stack is pressed: its faces lie at whole thicknesses from the
     * triangle's plane, with no empty level between the top and the bottom.
     */
    static void assertStackedAndPressed(Paper paper, Matrix4d toPlan, double size) {
        List<Face> faces = faces(paper, toPlan);
        double t = paper.thickness();
        double tolerance = 1e-9 * Math.max(size, paper.size());
        double margin = 1e-7 * size;
        for (Face a : faces) {
            assertTrue(a.flat, "face lies flat");
            for (Face b : faces) {
                if (a == b || a.maxX <= b.minX + margin || b.maxX <= a.minX + margin || a.maxY <= b.minY + margin
                        || b.maxY <= a.minY + margin || !ConvexOverlap.overlaps(a.shadow, b.shadow, margin)) {
                    continue;
                }
                double gap = Math.abs(a.height - b.height);
                assertTrue(gap >= t - tolerance, "overlapping layers lie a thickness apart: " + gap + " < " + t);
            }
        }
        if (t > 0) {
            TreeSet<Long> levels = new TreeSet<>();
            for (Face a : faces) {
                double level = a.height / t;
                assertTrue(Math.abs(level - Math.rint(level)) < 1e-6, "a face lies a whole number of thicknesses off the plane");
                levels.add(Math.round(level));
            }
            assertTrue(levels.first() <= 0 && levels.last() >= 0, "paper lies on the triangle");
            assertTrue(levels.last() - levels.first() + 1 == levels.size(), "pressed: no empty level in " + levels);
        }
    }

    private record Face(double[] shadow, double height, boolean flat, double minX, double maxX, double minY, double maxY) {
    }

    private static List<Face> faces(Paper paper, Matrix4d toPlan) {
        List<Face> faces = new ArrayList<>();
        Vector3d p = new Vector3d();
        for (int f = 0; f < paper.faceCount(); f++) {
            if (paper.isCap(f)) {
                continue;
            }
            int[] face = paper.face(f);
            double[] shadow = new double[2 * face.length];
            double low = Double.POSITIVE_INFINITY;
            double high = Double.NEGATIVE_INFINITY;
            double minX = Double.POSITIVE_INFINITY;
            double maxX = Double.NEGATIVE_INFINITY;
            double minY = Double.POSITIVE_INFINITY;
            double maxY = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < face.length; i++) {
                toPlan.transformPosition(p.set(paper.x(face[i]), paper.y(face[i]), paper.z(face[i])));
                shadow[2 * i] = p.x;
                shadow[2 * i + 1] = p.y;
                low = Math.min(low, p.z);
                high = Math.max(high, p.z);
                minX = Math.min(minX, p.x);
                maxX = Math.max(maxX, p.x);
                minY = Math.min(minY, p.y);
                maxY = Math.max(maxY, p.y);
            }
            faces.add(new Face(shadow, (low + high) / 2, high - low <= 1e-9 * Math.max(1, paper.size()), minX, maxX, minY, maxY));
        }
        return faces;
    }
}
