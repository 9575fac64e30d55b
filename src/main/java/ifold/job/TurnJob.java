package ifold.job;

import ifold.sheet.FoldException;
import ifold.wrap.PlacedWrap;
import ifold.wrap.TurnGadget;
import ifold.wrap.Wrap;
import ifold.wrap.WrapAnalysis;
import ifold.wrap.PaperInSpace;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The turn gadget, as {@code ifold demo turn} and the window's Fold, Turn gadget both do it: a
 * strip turned by an angle (the seed's Figures 1 and 2), placed in space and analysed, and the
 * figures of its report.
 */
public final class TurnJob {
    private TurnJob() {
    }

    /**
     * The turn made.
     *
     * @param figures the report's figures ({@link Reports#turn})
     * @param source what made it, as the exports' headers say: "demo turn --angle 90.0"
     */
    public record Outcome(TurnGadget.Result gadget, List<PaperInSpace> geometries, WrapAnalysis analysis, Map<String, Object> figures,
            String source) {
        /** The gadget's strip as a wrap of one strip, for the scenes and exports that show wraps. */
        public Wrap.Result result() {
            return gadget.wrap();
        }
    }

    /**
     * Makes the turn.
     *
     * @throws FoldException where the paper cannot be folded so
     */
    public static Outcome run(TurnGadget.Options options) throws FoldException {
        TurnGadget.Result gadget = TurnGadget.turn(options);
        PlacedWrap placed = PlacedWrap.of(gadget.wrap());
        Map<String, Object> figures = Reports.turn(options, gadget, placed.analysis());
        return new Outcome(gadget, placed.geometries(), placed.analysis(), figures,
                String.format(Locale.ROOT, "demo turn --angle %s", options.angle()));
    }
}
