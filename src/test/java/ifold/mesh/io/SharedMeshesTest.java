package ifold.mesh.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The third-party models of ../shared/meshes, checked against the numbers in its MANIFEST.md. */
class SharedMeshesTest {
    /** Relative to the working directory, which is the project directory for the test JVM. */
    private static final Path MESHES = Path.of("..", "shared", "meshes");

    private static Path model(String folder, String name) {
        Path dir = MESHES.resolve(folder);
        Assumptions.assumeTrue(Files.isDirectory(dir), () -> dir.toAbsolutePath() + " is absent");
        return dir.resolve(name);
    }

    /** Face sizes as the manifest writes them: "[3:13,4:12]". */
    private static String faceSizes(PolygonSoup soup) {
        Map<Integer, Integer> count = new TreeMap<>();
        for (int f = 0; f < soup.faceCount(); f++) {
            count.merge(soup.faceSize(f), 1, Integer::sum);
        }
        return count.entrySet().stream().map(e -> e.getKey() + ":" + e.getValue())
                .collect(Collectors.joining(",", "[", "]"));
    }

    /**
     * Every valid shared model written as PLY (binary and ASCII) reads back the same, vertex
     * for vertex, face for face, colours too; as STL it reads back the same triangles (in single
     * precision, the corners welded).
     */
    @ParameterizedTest(name = "{0}")
    @CsvSource({"cgal_elephant-with-holes.off", "cgal_elephant.off", "cgal_mesh_with_colors.off", "cgal_mpi.off",
        "cgal_tetrahedron.off", "common3d_spot.obj", "igl_fertility.off", "trimesh_capsule.obj", "trimesh_rabbit.obj"})
    void everyValidModelComesBackFromPlyAndStl(String name, @org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        PolygonSoup soup = MeshReaders.read(model("valid", name));
        for (boolean ascii : new boolean[] {false, true}) {
            Path ply = dir.resolve(ascii ? "a.ply" : "b.ply");
            MeshWriters.write(soup, ply, ascii);
            PolygonSoup back = MeshReaders.read(ply);
            assertEquals(soup.vertexCount(), back.vertexCount());
            assertEquals(soup.faceCount(), back.faceCount());
            for (int v = 0; v < soup.vertexCount(); v++) {
                for (int axis = 0; axis < 3; axis++) {
                    assertEquals(soup.coordinate(v, axis), back.coordinate(v, axis), 0, name + " vertex " + v);
                }
            }
            for (int f = 0; f < soup.faceCount(); f++) {
                assertEquals(soup.faceSize(f), back.faceSize(f));
                for (int k = 0; k < soup.faceSize(f); k++) {
                    assertEquals(soup.faceVertex(f, k), back.faceVertex(f, k));
                }
                if (soup.hasFaceColors()) {
                    assertEquals(soup.faceColor(f) & 0xFFFFFF, back.faceColor(f) & 0xFFFFFF);
                }
            }
            assertEquals(soup.hasFaceColors(), back.hasFaceColors());
            Path stl = dir.resolve(ascii ? "a.stl" : "b.stl");
            MeshWriters.write(soup, stl, ascii);
            PolygonSoup triangles = MeshReaders.read(stl);
            int t = 0;
            for (int f = 0; f < soup.faceCount(); f++) {
                for (int k = 1; k + 1 < soup.faceSize(f); k++, t++) {
                    int[] corners = {soup.faceVertex(f, 0), soup.faceVertex(f, k), soup.faceVertex(f, k + 1)};
                    for (int c = 0; c < 3; c++) {
                        for (int axis = 0; axis < 3; axis++) {
                            assertEquals((float) soup.coordinate(corners[c], axis), triangles.coordinate(triangles.faceVertex(t, c), axis), 0,
                                    name + " triangle " + t);
                        }
                    }
                }
            }
            assertEquals(t, triangles.faceCount());
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = ';', value = {
        "cgal_elephant-with-holes.off; 2798; 4463; [3:4463]",
        "cgal_elephant.off; 2775; 5558; [3:5558]",
        "cgal_mesh_with_colors.off; 8; 4; [3:3,5:1]",
        "cgal_mpi.off; 90; 52; [3:13,4:12,5:2,6:10,7:3,8:6,9:2,10:4]",
        "cgal_tetrahedron.off; 4; 4; [3:4]",
        "common3d_nefertiti.obj; 49971; 99938; [3:99938]",
        "common3d_spot.obj; 2930; 5856; [3:5856]",
        "igl_fertility.off; 4494; 9000; [3:9000]",
        "trimesh_capsule.obj; 5252; 10200; [3:10200]",
        "trimesh_rabbit.obj; 644; 678; [3:176,4:496,16:6]",
    })
    void readsEveryValidModel(String name, int vertices, int faces, String sizes) throws Exception {
        PolygonSoup soup = MeshReaders.read(model("valid", name));
        assertEquals(vertices, soup.vertexCount(), "vertices");
        assertEquals(faces, soup.faceCount(), "faces");
        assertEquals(sizes, faceSizes(soup), "face sizes");
        for (int f = 0; f < soup.faceCount(); f++) {
            assertTrue(soup.faceLine(f) > 0, "face " + f + " has a source line");
        }
    }

    @Test
    void everyValidModelIsChecked() throws IOException {
        Path dir = model("valid", ".").getParent();
        TreeSet<String> listed = new TreeSet<>(java.util.List.of("cgal_elephant-with-holes.off", "cgal_elephant.off",
                "cgal_mesh_with_colors.off", "cgal_mpi.off", "cgal_tetrahedron.off", "common3d_nefertiti.obj",
                "common3d_spot.obj", "igl_fertility.off", "trimesh_capsule.obj", "trimesh_rabbit.obj"));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(listed, files.map(p -> p.getFileName().toString()).collect(Collectors.toCollection(TreeSet::new)));
        }
    }

    @Test
    void readsTheColoursOfCgalMeshWithColors() throws Exception {
        PolygonSoup soup = MeshReaders.read(model("valid", "cgal_mesh_with_colors.off"));
        // "0.9 0 0" and "0 0 0.9": 0.9 * 255 rounds to 230 = 0xE6.
        assertEquals(0xFFE60000, soup.faceColor(0));
        assertEquals(0xFFE60000, soup.faceColor(2));
        assertEquals(0xFF0000E6, soup.faceColor(3));
        assertEquals(5, soup.faceSize(3));
        assertEquals(23, soup.faceLine(3));
        // Vertex colours are skipped, not read as coordinates: "1 -1 0 0.9 0 0#red".
        assertEquals(1.0, soup.coordinate(2, 0));
        assertEquals(-1.0, soup.coordinate(2, 1));
        assertEquals(0.0, soup.coordinate(2, 2));
    }

    /**
     * Each broken model fails at the line the manifest names. Where it names none: the huge
     * vertex count is refused on its header line; the truncated elephant stops on its last
     * line, 4220, inside face 1441 counted from 0 (the manifest's "face 1441"). For test-nan the
     * manifest's strict parser accepts "nan" and "inf" and stops at "1.#IND" on line 14; iFold
     * refuses every non-finite coordinate, so it stops at the first, "nan" on line 12.
     */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = ';', value = {
        "assimp_OutOfMemory.off; 2; the header claims 353535235358 vertices",
        "assimp_empty.off; 0; empty file",
        "assimp_malformed.obj; 28; face index 0",
        "elephant_truncated_midline.off; 4220; truncated: the file ends after 1441 of 5558 faces, inside a face that"
            + " declares 3 vertices and has 1",
        "tetrahedron_index_out_of_range.off; 10; vertex index 4 out of range: the file has 4 vertices",
        "tinyobj_issue-140-zero-face-idx.obj; 16; face index 0",
        "tinyobj_test-nan.obj; 12; coordinate 'nan' is not a finite number",
        "trimesh_notenoughindices.obj; 9; face with 2 vertices, need at least 3",
    })
    void refusesEveryInvalidModel(String name, int line, String phrase) {
        Path file = model("invalid", name);
        MeshFormatException e = assertThrows(MeshFormatException.class, () -> MeshReaders.read(file));
        assertEquals(line, e.line(), e.getMessage());
        assertTrue(e.problem().contains(phrase), e.getMessage());
        assertTrue(e.getMessage().startsWith(file.toString()), e.getMessage());
    }
}
