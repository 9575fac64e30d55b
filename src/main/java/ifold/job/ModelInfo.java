package ifold.job;

import ifold.mesh.Defect;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.MeshValidator;
import ifold.mesh.Topology;
import ifold.mesh.io.MeshReaders;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * What a model is, as a surface, after loading and repair: the figures {@code ifold info}
 * prints and the window's Model information shows, in the order and under the names of
 * {@code ifold info --json}.
 */
public final class ModelInfo {
    private ModelInfo() {
    }

    /**
     * The model's counts and topology: the file's own counts, the mesh's, the size of its faces,
     * boundary loops, components, Euler characteristic, genus, whether it was manifold as given
     * and is valid as built, and the repairs made by kind.
     *
     * @param file the model's name as the user gave it
     * @param read the format read, and for STL the corners welded
     * @param inputVertices vertices in the file
     * @param inputFaces faces in the file
     * @param built the mesh built from the file, with its repairs
     */
    public static Map<String, Object> of(String file, MeshReaders.Read read, int inputVertices, int inputFaces, MeshBuilder.Result built) {
        HalfedgeMesh mesh = built.mesh();
        Topology topology = Topology.of(mesh);
        boolean valid = MeshValidator.validate(mesh).isEmpty();
        Map<Defect, Integer> repairs = built.repairs();
        // The input was manifold if nothing had to be split or cut to make it so.
        boolean manifold = !repairs.containsKey(Defect.NON_MANIFOLD_EDGE) && !repairs.containsKey(Defect.NON_MANIFOLD_VERTEX);
        Map<String, Object> report = new LinkedHashMap<>();
        report.put("file", file);
        report.put("format", read.format());
        if (read.weldedCorners() >= 0) {
            report.put("weldedCorners", read.weldedCorners());
        }
        report.put("inputVertices", inputVertices);
        report.put("inputFaces", inputFaces);
        report.put("vertices", topology.vertices());
        report.put("faces", topology.faces());
        report.put("edges", topology.edges());
        report.put("faceSizes", faceSizes(mesh));
        report.put("boundaryLoops", topology.boundaryLoops());
        report.put("closed", topology.boundaryLoops() == 0);
        report.put("components", topology.components());
        report.put("eulerCharacteristic", topology.eulerCharacteristic());
        report.put("genus", topology.genus());
        report.put("manifold", manifold);
        report.put("valid", valid);
        report.put("repairs", Reports.repairs(repairs));
        return report;
    }

    /** How many faces have each number of sides, e.g. {3: 176, 4: 496}. */
    private static Map<String, Object> faceSizes(HalfedgeMesh mesh) {
        TreeMap<Integer, Integer> sizes = new TreeMap<>();
        for (int f = 0; f < mesh.faceCount(); f++) {
            sizes.merge(mesh.faceSize(f), 1, Integer::sum);
        }
        Map<String, Object> result = new LinkedHashMap<>();
        sizes.forEach((size, count) -> result.put(Integer.toString(size), count));
        return result;
    }
}
