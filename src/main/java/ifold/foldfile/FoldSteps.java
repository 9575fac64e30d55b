package ifold.foldfile;

import com.fasterxml.jackson.core.JsonGenerator;
import ifold.script.FoldScript;
import ifold.script.FoldScriptException;
import ifold.sheet.HostFrame;
import ifold.sheet.Sheet;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * A fold script's folding sequence as FOLD frames ({@code --fold-frames}): after each fold, the
 * paper as it then stands — its faces, edges with their assignments and fold angles, vertices
 * in space and face orders — a frame of its own in {@code file_frames} after the folded state,
 * as ORIPA, Oriedita and Origami Simulator users ask for a folding sequence. The paper is
 * folded again without thickness, as FOLD's folded state is, and each frame taken as the fold
 * ends (its faces as that fold has cut them: a frame does not inherit the key frame's).
 */
public final class FoldSteps {
    /** One frame: what the FOLD writer made of the paper after a fold. */
    private record Frame(String title, List<double[]> vertices, List<int[]> faces, List<int[]> edges, List<String> assignments,
            List<Double> angles, List<int[]> orders) {
    }

    private final List<Frame> frames = new ArrayList<>();

    private FoldSteps() {
    }

    /**
     * The frames of {@code script}: folded again on ideal paper, a frame after each fold.
     *
     * @throws FoldScriptException where it does not fold without thickness (a fold line given in
     *     space can lie off the paper once the layers have none)
     */
    public static FoldSteps of(FoldScript script, int maxFaces) throws FoldScriptException {
        FoldSteps steps = new FoldSteps();
        int folds = script.steps().size();
        script.withThickness(0).play(new long[folds], maxFaces, (k, sheet, planes) -> steps.add(
                String.format(Locale.ROOT, "after fold %d of %d", k + 1, folds), sheet, planes));
        return steps;
    }

    /** How many frames: a fold each. */
    public int size() {
        return frames.size();
    }

    private void add(String title, Sheet sheet, HostFrame[] planes) {
        FoldFile.Folded folded = new FoldFile.Folded(sheet, planes);
        FoldFile.Pattern pattern = new FoldFile.Pattern(List.of(folded));
        List<int[]> faces = new ArrayList<>();
        for (int f = 0; f < sheet.faceCount(); f++) {
            faces.add(sheet.loop(f).clone());
        }
        List<int[]> edges = new ArrayList<>();
        for (int[] edge : pattern.edges) {
            edges.add(new int[] {edge[0], edge[1]});
        }
        frames.add(new Frame(title, FoldFile.foldedVertices(folded), faces, edges, List.copyOf(pattern.assignments),
                List.copyOf(pattern.angles), List.copyOf(pattern.orders)));
    }

    /** Writes the frames, each a JSON object of {@code file_frames}. */
    void writeTo(JsonGenerator json) throws IOException {
        for (Frame frame : frames) {
            json.writeStartObject();
            json.writeStringField("frame_title", frame.title());
            FoldFile.Pattern.stringArray(json, "frame_classes", "foldedForm");
            FoldFile.Pattern.stringArray(json, "frame_attributes", "3D");
            json.writeNumberField("frame_parent", 0);
            json.writeBooleanField("frame_inherit", false);
            FoldFile.Pattern.points(json, "vertices_coords", frame.vertices());
            writeLists(json, "edges_vertices", frame.edges());
            json.writeFieldName("edges_assignment");
            json.writeStartArray();
            for (String assignment : frame.assignments()) {
                json.writeString(assignment);
            }
            json.writeEndArray();
            json.writeFieldName("edges_foldAngle");
            json.writeStartArray();
            for (double angle : frame.angles()) {
                json.writeNumber(angle);
            }
            json.writeEndArray();
            writeLists(json, "faces_vertices", frame.faces());
            writeLists(json, "faceOrders", frame.orders());
            json.writeEndObject();
        }
    }

    private static void writeLists(JsonGenerator json, String field, List<int[]> lists) throws IOException {
        json.writeFieldName(field);
        json.writeStartArray();
        for (int[] list : lists) {
            json.writeStartArray();
            for (int value : list) {
                json.writeNumber(value);
            }
            json.writeEndArray();
        }
        json.writeEndArray();
    }
}
