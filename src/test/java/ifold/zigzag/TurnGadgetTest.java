package ifold.zigzag;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.fold.Paper;
import ifold.fold.PaperAnalysis;
import ifold.mesh.MeshValidator;
import java.util.List;
import org.joml.Matrix4d;
import org.junit.jupiter.api.Test;

class TurnGadgetTest {
    @Test
    void turnsByAnyAngleTopSideUp() throws Exception {
        for (double angle : new double[] {1, 30, 45, 60, 90, 120, 150, 179}) {
            for (double overhang : new double[] {0, 0.5, 2}) {
                TurnGadget.Result gadget = TurnGadget.turn(angle, overhang, 1, 0.02, 4, 4);
                String what = angle + " degrees, overhang " + overhang;
                assertEquals(angle, gadget.measuredAngle(), 1e-9, what);
                assertTrue(gadget.endFacesUp(), "top side up after " + what);
                Paper paper = gadget.folded();
                assertTrue(PaperAnalysis.isometryError(paper) <= 1e-9, what);
                assertEquals(List.of(), MeshValidator.validate(paper.top()), what);
                assertEquals(gadget.length(), PaperAnalysis.paperArea(paper), 1e-9 * gadget.length(), what);
                Layers.assertStackedAndPressed(paper, new Matrix4d(), gadget.length());
                int layers = PaperAnalysis.maxLayers(paper);
                assertTrue(layers >= 2 && layers <= 3, "at most the strip, the part laid back and the part turned: " + what);
            }
        }
    }

    @Test
    void theBasicGadgetsCreasesTouchAtTheStripsEdge() throws Exception {
        TurnGadget.Result gadget = TurnGadget.turn(90, 0, 1, 0.01, 3, 3);
        // Crease across at u = 3, turn crease from (3, 0) to (4, 1): 3 + 1 + 3 of strip.
        assertEquals(7, gadget.length(), 1e-12);
        assertEquals(90, gadget.measuredAngle(), 1e-9);
    }

    @Test
    void badTurnsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> TurnGadget.turn(0, 0, 1, 0.01, 3, 3));
        assertThrows(IllegalArgumentException.class, () -> TurnGadget.turn(180, 0, 1, 0.01, 3, 3));
        assertThrows(IllegalArgumentException.class, () -> TurnGadget.turn(90, -1, 1, 0.01, 3, 3));
        assertThrows(IllegalArgumentException.class, () -> TurnGadget.turn(Double.NaN, 0, 1, 0.01, 3, 3));
    }
}
