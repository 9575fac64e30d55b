package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.check.WrapTruths;
import ifold.geom.ParameterException;
import ifold.sheet.Sheet;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TurnGadgetTest {
    @TempDir
    Path dir;

    @Test
    void turnsByAnyAngleTopSideUp() throws Exception {
        for (double angle : new double[] {1, 30, 45, 60, 90, 120, 150, 179}) {
            for (double overhang : new double[] {0, 0.5, 2}) {
                TurnGadget.Result gadget = TurnGadget.turn(angle, overhang, 1, 0.02, 4, 4);
                String what = angle + " degrees, overhang " + overhang;
                assertEquals(angle, gadget.measuredAngle(), 1e-9, what);
                assertTrue(gadget.endFacesUp(), "top side up after " + what);
                Wrap.Result result = gadget.wrap();
                PaperInSpace geometry = PaperInSpace.of(gadget.sheet(), result.frames());
                WrapAnalysis analysis = WrapAnalysis.of(result, List.of(geometry));
                assertTrue(analysis.isometryError() <= 1e-9, what);
                assertEquals(2, result.count(Wrap.Kind.TURN_GADGET), what);
                int layers = analysis.maxLayers();
                assertTrue(layers >= 2 && layers <= 3, "at most the strip, the part laid back and the part turned: " + what);
                // The file tells the same: one strip tiling its rectangle, not stretched, not torn, on the table.
                Path obj = dir.resolve("turn.obj");
                WrapExport.writeObj(obj, "turn", result, List.of(geometry));
                WrapTruths truths = WrapTruths.read(Files.readString(obj));
                double[] table = new double[9];
                for (int k = 0; k < 3; k++) {
                    for (int axis = 0; axis < 3; axis++) {
                        table[3 * k + axis] = result.mesh().coordinate(result.mesh().faceVertex(0, k), axis);
                    }
                }
                List<WrapTruths.Violation> violations = truths.check(List.<double[]>of(table), 0.02, analysis.stackLevels(), 0, 1);
                assertTrue(violations.isEmpty(), what + ": " + violations);
                assertEquals(gadget.length(), truths.length(0), 1e-9 * gadget.length(), what);
            }
        }
    }

    @Test
    void theBasicGadgetsCreasesTouchAtTheStripsEdge() throws Exception {
        TurnGadget.Result gadget = TurnGadget.turn(90, 0, 1, 0.01, 3, 3);
        // Crease across at u = 3, turn crease from (3, 0) to (4, 1): 3 + 1 + 3 of strip.
        assertEquals(7, gadget.length(), 1e-12);
        assertEquals(90, gadget.measuredAngle(), 1e-9);
        Sheet sheet = gadget.sheet();
        assertEquals(3, sheet.faceCount(), "the lead, the triangle between the creases, the tail");
        assertEquals(3, sheet.loop(1).length, "the creases meet at the strip's edge: the face between them is a triangle");
    }

    @Test
    void badTurnsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> TurnGadget.turn(0, 0, 1, 0.01, 3, 3));
        assertThrows(IllegalArgumentException.class, () -> TurnGadget.turn(180, 0, 1, 0.01, 3, 3));
        assertThrows(IllegalArgumentException.class, () -> TurnGadget.turn(90, -1, 1, 0.01, 3, 3));
        assertThrows(IllegalArgumentException.class, () -> TurnGadget.turn(Double.NaN, 0, 1, 0.01, 3, 3));
        assertThrows(IllegalArgumentException.class, () -> TurnGadget.turn(90, 0, 1, -0.01, 3, 3));
    }

    @Test
    void optionsCheckEveryValueAndNameIt() throws Exception {
        assertParameter("angle", () -> new TurnGadget.Options(0.005, 0, 1, Double.NaN));
        assertParameter("angle", () -> new TurnGadget.Options(179.95, 0, 1, Double.NaN));
        assertParameter("angle", () -> new TurnGadget.Options(Double.NaN, 0, 1, Double.NaN));
        assertParameter("overhang", () -> new TurnGadget.Options(90, -0.5, 1, Double.NaN));
        assertParameter("overhang", () -> new TurnGadget.Options(90, 101, 1, Double.NaN));
        assertParameter("width", () -> new TurnGadget.Options(90, 0, 0, Double.NaN));
        assertParameter("thickness", () -> new TurnGadget.Options(90, 0, 1, 0.3));
        TurnGadget.Options options = new TurnGadget.Options(TurnGadget.Options.MAX_ANGLE, 2, 0.5, Double.NaN);
        assertEquals(0.01, options.thickness(), 0, "a fiftieth of the width by default");
        TurnGadget.Result gadget = TurnGadget.turn(options);
        assertEquals(179.9, gadget.measuredAngle(), 1e-6, "the whole range turns");
        assertEquals(1.0, gadget.overhang(), 0, "the overhang is given in widths");
        assertEquals(0.01, TurnGadget.turn(new TurnGadget.Options(0.01, 0, 1, 0)).measuredAngle(), 1e-9);
    }

    private static void assertParameter(String parameter, org.junit.jupiter.api.function.Executable make) {
        ParameterException e = assertThrows(ParameterException.class, make);
        assertEquals(parameter, e.parameter(), e.getMessage());
    }
}
