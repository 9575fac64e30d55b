package ifold.job;

import ifold.check.LayerOrder;
import ifold.foldfile.FoldFile;
import java.io.IOException;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The layer-order check of folded paper, as the report gives it: the independent checker
 * ({@link LayerOrder}) reads the paper's FOLD file, the one exported where there is one, else the
 * same text made in memory, never the engine's own stacks.
 */
public final class LayerOrders {
    private LayerOrders() {
    }

    /** The most faces checked: beyond, the FOLD text alone is hundreds of megabytes. */
    public static final int MOST_FACES = 200_000;

    /** Why {@code sheets} are not checked, or null where they are. */
    public static String notChecked(List<FoldFile.Folded> sheets) {
        long faces = 0;
        for (FoldFile.Folded sheet : sheets) {
            faces += sheet.sheet().faceCount();
        }
        return faces > MOST_FACES ? faces + " faces of paper, more than the " + MOST_FACES + " checked" : null;
    }

    /**
     * Checks the sheets' layer order, reading {@code exported} (the FOLD file written of them)
     * where it is not null; null where {@link #notChecked} says why not.
     */
    public static LayerOrder.Result check(List<FoldFile.Folded> sheets, String title, Path exported) throws IOException {
        if (notChecked(sheets) != null) {
            return null;
        }
        if (exported != null) {
            try (Reader reader = Files.newBufferedReader(exported, StandardCharsets.UTF_8)) {
                return LayerOrder.check(reader);
            }
        }
        return LayerOrder.check(FoldFile.text(title, sheets));
    }

    /**
     * Checks the sheets as {@link #check} does and adds {@code layerOrder} to a report's figures:
     * {@code "valid"}, or the violations by kind and the first in words.
     */
    public static LayerOrder.Result addTo(Map<String, Object> figures, List<FoldFile.Folded> sheets, String title, Path exported)
            throws IOException {
        LayerOrder.Result result = check(sheets, title, exported);
        figures.put("layerOrder", result == null ? Map.of("notChecked", notChecked(sheets)) : figures(result));
        return result;
    }

    /** As {@link #addTo(Map, List, String, Path)} on the FOLD text made in memory. */
    public static LayerOrder.Result addTo(Map<String, Object> figures, List<FoldFile.Folded> sheets, String title) {
        try {
            return addTo(figures, sheets, title, null);
        } catch (IOException e) {
            throw new UncheckedIOException(e); // no file is read
        }
    }

    /** {@code "valid"}, or the count of violations, by kind, and the first few in words. */
    public static Object figures(LayerOrder.Result result) {
        if (result.valid()) {
            return "valid";
        }
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("violations", result.total());
        for (Map.Entry<LayerOrder.Kind, Integer> entry : result.violations().entrySet()) {
            if (entry.getValue() > 0) {
                figures.put(entry.getKey().key, entry.getValue());
            }
        }
        figures.put("first", result.first().stream().map(LayerOrder.Violation::message).toList());
        return figures;
    }
}
