package ifold.ui.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The names Save dialogs suggest: what is shown, with the export's extension, never the opened file's own name. */
class ExportsTest {
    @Test
    void saveDialogsSuggestTheModelsNameAndTheExtension() {
        assertEquals("zigzag.mp4", Exports.suggestedName(Job.ZigZag.DEMO, "mp4"));
        assertEquals("turn.obj", Exports.suggestedName(new Job.Turn("60", "", "", ""), "obj"));
        Path cube = Path.of("models", "cube.off");
        assertEquals("cube.fold", Exports.suggestedName(new Job.WrapModel(cube, "", "", "", false), "fold"));
        assertEquals("cube-export.off", Exports.suggestedName(new Job.WrapModel(cube, "", "", "", false), "off"),
                "saving as suggested does not write over the model");
        assertEquals("pleat20.json", Exports.suggestedName(new Job.Script(Path.of("models/scripts/pleat20.fold")), "json"));
        assertEquals("pleat20-export.fold", Exports.suggestedName(new Job.Script(Path.of("models/scripts/pleat20.fold")), "fold"));
    }
}
