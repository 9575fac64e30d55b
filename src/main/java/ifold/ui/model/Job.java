package ifold.ui.model;

import ifold.wrap.Wrap;

import ifold.job.Scenes;
import ifold.scene.PathView;
import java.nio.file.Path;

/**
 * What the window folds, with its parameters as the user typed them: text, so that a value
 * that is not a number is the field's error like any other. A blank width or thickness is the
 * core's default, as an option left out on the command line.
 */
public sealed interface Job {

    /**
     * The zig-zag demo: one triangle wrapped by one strip.
     *
     * @param triangle the corners, {@code x1,y1,x2,y2,x3,y3} (or nine numbers in space)
     * @param start the corner the strip starts at (0, 1, 2 for A, B, C)
     * @param end the corner it ends at
     * @param enterFrom the corner beside which it comes in, or -1 to let the planner choose
     */
    record ZigZag(String triangle, int start, int end, int enterFrom, String width, String thickness) implements Job {
        /** The command line's default: {@code ifold demo zigzag}. */
        public static final ZigZag DEMO = new ZigZag("0,0,10,0,3.5,8", 2, 0, -1, "", "");
    }

    /** The turn gadget: a strip turned by {@code angle} degrees, {@code overhang} strip widths beyond the fold across. */
    record Turn(String angle, String overhang, String width, String thickness) implements Job {
        public static final Turn DEMO = new Turn("60", "0", "1", "");
    }

    /**
     * A model (OFF or OBJ) wrapped along its Hamiltonian path.
     *
     * @param maxFaces the most faces of paper the wrap may make; blank for the command line's default
     * @param strict refuse defective input instead of repairing it, as {@code --strict}
     */
    record WrapModel(Path model, String width, String thickness, String maxFaces, boolean strict, Wrap.Method method) implements Job {
        public WrapModel {
            method = method == null ? Wrap.Method.ZIGZAG : method;
        }

        public WrapModel(Path model, String width, String thickness, String maxFaces, boolean strict) {
            this(model, width, thickness, maxFaces, strict, Wrap.Method.ZIGZAG);
        }

        public WrapModel(Path model, String width, String thickness) {
            this(model, width, thickness, "", false);
        }

        public WrapModel(Path model, String width, String thickness, String maxFaces) {
            this(model, width, thickness, maxFaces, false);
        }
    }

    /**
     * A fold script, or a FOLD file.
     *
     * @param maxFaces the most faces the folds may cut the paper into; blank for the command line's default
     */
    record Script(Path file, String maxFaces) implements Job {
        /** The script with the command line's limit on faces. */
        public Script(Path file) {
            this(file, "");
        }
    }

    /**
     * A model looked at, as {@code ifold view} shows it: as it is, its Hamiltonian refinement
     * ({@code --refine}), or the path revealed triangle by triangle ({@code --path}).
     *
     * @param colors how the path colours its triangles ({@code --colors}); the path's only
     * @param strict refuse defective input instead of repairing it, as {@code --strict}
     */
    record View(Path model, Scenes.Show show, PathView.Colors colors, boolean strict) implements Job {
    }
}
