package ifold.mesh;

import java.util.Locale;

/**
 * The kinds of trouble {@link MeshBuilder} finds in real input. Each kind but the first two can
 * be repaired; {@code --strict} refuses any of them instead.
 */
public enum Defect {
    /** A face refers to a vertex that does not exist; never repaired. */
    INDEX_OUT_OF_RANGE("vertex index out of range", "", "", false),
    /** A coordinate is NaN or infinite; never repaired. */
    NON_FINITE_COORDINATE("non-finite coordinate", "", "", false),
    /** A face lists the same vertex twice in a row; the repeat is removed. */
    REPEATED_VERTEX("face repeats a vertex", "removed repeated corners from 1 face", "removed repeated corners from %d faces", true),
    /** A face has fewer than three distinct vertices, or visits a vertex twice; dropped. */
    DEGENERATE_FACE("face has fewer than three distinct vertices", "dropped 1 degenerate face", "dropped %d degenerate faces", true),
    /** A face (or a triangle of it) has no area; dropped. */
    ZERO_AREA_FACE("face has zero area", "dropped 1 zero-area face", "dropped %d zero-area faces", true),
    /** A face has the same vertices as an earlier one; dropped. */
    DUPLICATE_FACE("face duplicates an earlier face", "dropped 1 duplicate face", "dropped %d duplicate faces", true),
    /** More than two faces share an edge; it is split so that at most two stay joined. */
    NON_MANIFOLD_EDGE("edge shared by more than two faces", "split 1 non-manifold edge", "split %d non-manifold edges", true),
    /** A vertex where surface sheets touch at a point (a pinch); split into one vertex per sheet. */
    NON_MANIFOLD_VERTEX("vertex where sheets touch at a point", "split 1 non-manifold vertex", "split %d non-manifold vertices", true),
    /** A face oriented against its neighbours; turned over. */
    INCONSISTENT_ORIENTATION("face oriented against its neighbours", "re-oriented 1 face", "re-oriented %d faces", true),
    /** A loop of faces that cannot be oriented (a Moebius band); cut open along an edge. */
    NON_ORIENTABLE("surface is not orientable", "cut 1 edge to make a non-orientable part orientable", "cut %d edges to make non-orientable parts orientable", true),
    /** A closed component whose faces all point inward; turned outward. */
    INWARD_COMPONENT("closed component faces inward", "turned 1 inward-facing closed component outward", "turned %d inward-facing closed components outward", true),
    /** A vertex that no face uses; removed. */
    UNREFERENCED_VERTEX("vertex used by no face", "removed 1 unreferenced vertex", "removed %d unreferenced vertices", true);

    private final String description;
    /** What one repair did, and what several did (a format of their count). */
    private final String repairOne;
    private final String repairFormat;
    private final boolean repairable;

    Defect(String description, String repairOne, String repairFormat, boolean repairable) {
        this.description = description;
        this.repairOne = repairOne;
        this.repairFormat = repairFormat;
        this.repairable = repairable;
    }

    /** What is wrong, as a phrase ("edge shared by more than two faces"). */
    public String description() {
        return description;
    }

    /** Whether the builder can repair it (when not strict). */
    public boolean isRepairable() {
        return repairable;
    }

    /** What the repair did, given how many times ("split 3 non-manifold edges", "split 1 non-manifold edge"). */
    public String describeRepair(int count) {
        return count == 1 ? repairOne : String.format(Locale.ROOT, repairFormat, count);
    }
}
