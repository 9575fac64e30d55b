package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A folded paper read back from the OBJ iFold wrote: how far each paper edge's length in space
 * ({@code v}) strays from its length on the sheet ({@code vt}), and the faces in each group.
 *
 * @param worstIsometry the largest relative difference over the paper faces' edges
 * @param vertices the {@code v} lines
 * @param paperFaces faces in group {@code paper}
 * @param capFaces faces in group {@code cap}
 */
record ObjReadBack(double worstIsometry, int vertices, int paperFaces, int capFaces) {

    static ObjReadBack read(Path obj) throws Exception {
        List<double[]> v = new ArrayList<>();
        List<double[]> vt = new ArrayList<>();
        String group = "";
        int paperFaces = 0;
        int capFaces = 0;
        double worst = 0;
        for (String line : Files.readAllLines(obj)) {
            String[] w = line.split(" ");
            switch (w[0]) {
                case "v" -> v.add(new double[] {Double.parseDouble(w[1]), Double.parseDouble(w[2]), Double.parseDouble(w[3])});
                case "vt" -> vt.add(new double[] {Double.parseDouble(w[1]), Double.parseDouble(w[2])});
                case "g" -> group = w[1];
                case "f" -> {
                    if (group.equals("cap")) {
                        capFaces++;
                        continue;
                    }
                    paperFaces++;
                    for (int i = 1; i < w.length; i++) {
                        int a = Integer.parseInt(w[i].split("/")[0]) - 1;
                        int b = Integer.parseInt(w[i % (w.length - 1) + 1].split("/")[0]) - 1;
                        double space = Math.sqrt(Math.pow(v.get(a)[0] - v.get(b)[0], 2) + Math.pow(v.get(a)[1] - v.get(b)[1], 2)
                                + Math.pow(v.get(a)[2] - v.get(b)[2], 2));
                        double paper = Math.hypot(vt.get(a)[0] - vt.get(b)[0], vt.get(a)[1] - vt.get(b)[1]);
                        worst = Math.max(worst, Math.abs(space - paper) / paper);
                    }
                }
                default -> {
                }
            }
        }
        assertEquals(v.size(), vt.size(), "a vt for every v");
        return new ObjReadBack(worst, v.size(), paperFaces, capFaces);
    }
}
