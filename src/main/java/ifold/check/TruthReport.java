package ifold.check;

import ifold.check.WrapTruths.Violation;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** The violations as they are found, listing at most LISTED_PER_TRUTH of each truth. */
final class TruthReport {
    private final Map<String, List<Violation>> byTruth = new LinkedHashMap<>();
    private final Map<String, Integer> counts = new HashMap<>();
    private final Map<String, Violation> summaries = new HashMap<>();

    TruthReport() {
        for (String truth : List.of(WrapTruths.TILED, WrapTruths.ISOMETRIC, WrapTruths.NOT_TORN, WrapTruths.COVERED, WrapTruths.ON_SURFACE)) {
            byTruth.put(truth, new ArrayList<>());
        }
    }

    void add(String truth, String message) {
        int count = counts.merge(truth, 1, Integer::sum);
        if (count <= WrapTruths.LISTED_PER_TRUTH) {
            byTruth.get(truth).add(new Violation(truth, message));
        }
    }

    /** How many violations of each truth were found, in truth order; the truths that hold left out. */
    Map<String, Integer> counts() {
        Map<String, Integer> found = new LinkedHashMap<>();
        for (String truth : byTruth.keySet()) {
            if (counts.containsKey(truth)) {
                found.put(truth, counts.get(truth));
            }
        }
        return found;
    }

    /** A line that sums up a truth's violations (how many of the points tried): listed, not counted as one more. */
    void summary(String truth, String message) {
        summaries.put(truth, new Violation(truth, message));
    }

    List<Violation> finish() {
        List<Violation> all = new ArrayList<>();
        byTruth.forEach((truth, list) -> {
            all.addAll(list);
            if (summaries.containsKey(truth)) {
                all.add(summaries.get(truth));
            }
            int count = counts.getOrDefault(truth, 0);
            if (count > WrapTruths.LISTED_PER_TRUTH) {
                all.add(new Violation(truth, (count - WrapTruths.LISTED_PER_TRUTH) + " more violations of this truth not listed"));
            }
        });
        return List.copyOf(all);
    }
}
