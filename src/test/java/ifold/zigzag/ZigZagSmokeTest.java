package ifold.zigzag;

import ifold.fold.Paper;
import org.joml.Matrix4d;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

class ZigZagSmokeTest {
    @Test
    void prints() throws Exception {
        ZigZag.Result r = ZigZag.wrap(Triangle.planar(0, 0, 10, 0, 3.5, 8), new ZigZag.Options(1.6, 0.02, 2, 0, -1));
        Matrix4d toPlan = r.planToSpace().invert(new Matrix4d());
        double[] plan = r.triangle().inPlan(2);
        for (int k = 0; k <= r.steps().size(); k++) {
            Paper p = k == 0 ? r.start() : r.steps().get(k - 1).prepared().at(1);
            java.util.TreeSet<Double> zs = new java.util.TreeSet<>();
            for (int f = 0; f < p.faceCount(); f++) if (!p.isCap(f)) for (int v : p.face(f)) zs.add(Math.rint(p.z(v) * 1000) / 1000);
            System.out.println(k + " far " + Outside.farthestFromTriangle(p, toPlan, plan) + " heights " + zs);
        }
    }
}
