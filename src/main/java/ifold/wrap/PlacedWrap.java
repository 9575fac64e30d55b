package ifold.wrap;

import java.util.ArrayList;
import java.util.List;

/**
 * A wrap's paper placed in space, strip by strip, and its measures: what every front end shows,
 * exports and reports after a wrap.
 *
 * <p>The two are taken at once: the workers arrange each host's faces for the measures while
 * this thread places the paper, which needs none of that (on two cores the workers keep both
 * busy already, so this saves little: the 5,120-triangle icosphere's placing and measures took
 * 6.6 s where they took 6.8 one after the other).
 *
 * @param geometries each strip's paper in space, in the order of the strips
 * @param analysis the wrap's measures
 */
public record PlacedWrap(List<PaperInSpace> geometries, WrapAnalysis analysis) {

    public static PlacedWrap of(Wrap.Result result) {
        WrapAnalysis.Started measuring = WrapAnalysis.start(result);
        List<PaperInSpace> geometries = new ArrayList<>();
        try {
            for (Wrap.Strip strip : result.strips()) {
                geometries.add(PaperInSpace.of(strip.sheet(), result.frames()));
            }
        } catch (RuntimeException | Error e) {
            measuring.cancel();
            throw e;
        }
        return new PlacedWrap(List.copyOf(geometries), measuring.finish(geometries));
    }
}
