package ifold.ui;

import ifold.job.Scenes;
import ifold.scene.PathView;
import ifold.ui.model.Job;
import ifold.ui.model.Settings;
import java.io.IOException;

/**
 * What the window remembers between sessions (Java preferences): each job's fields, the last
 * folder, the window's place and size, the paper's colours.
 */
final class WindowSettings {
    private final MainWindow window;

    WindowSettings(MainWindow window) {
        this.window = window;
    }

    void rememberParameters(Job job) {
        if (job instanceof Job.ZigZag z) {
            window.settings.put("zigzag.triangle", z.triangle());
            window.settings.putInt("zigzag.start", z.start());
            window.settings.putInt("zigzag.end", z.end());
            window.settings.putInt("zigzag.enterFrom", z.enterFrom());
            window.settings.put("zigzag.width", z.width());
            window.settings.put("zigzag.thickness", z.thickness());
        } else if (job instanceof Job.Turn t) {
            window.settings.put("turn.angle", t.angle());
            window.settings.put("turn.overhang", t.overhang());
            window.settings.put("turn.width", t.width());
            window.settings.put("turn.thickness", t.thickness());
        } else if (job instanceof Job.WrapModel w) {
            window.settings.put("wrap.width", w.width());
            window.settings.put("wrap.thickness", w.thickness());
            window.settings.put("wrap.maxFaces", w.maxFaces());
            window.settings.put("wrap.strict", Boolean.toString(w.strict()));
            window.settings.put("wrap.method", w.method().word());
        } else if (job instanceof Job.Script s) {
            window.settings.put("script.maxFaces", s.maxFaces());
        } else if (job instanceof Job.View v) {
            window.settings.put("view.show", v.show().name());
            window.settings.put("view.colors", v.colors().name());
            window.settings.put("view.strict", Boolean.toString(v.strict()));
        }
        window.settings.put("job", job instanceof Job.ZigZag ? "zigzag" : job instanceof Job.Turn ? "turn" : job instanceof Job.WrapModel
                ? "wrap" : job instanceof Job.View ? "view" : "script");
    }

    /** The zig-zag as it was left last time, or the demo. */
    Job.ZigZag rememberedZigZag() {
        Job.ZigZag demo = Job.ZigZag.DEMO;
        return new Job.ZigZag(window.settings.get("zigzag.triangle", demo.triangle()), clampCorner(window.settings.getInt("zigzag.start", demo.start()), 0),
                clampCorner(window.settings.getInt("zigzag.end", demo.end()), 0), Math.max(-1, Math.min(2, window.settings.getInt("zigzag.enterFrom", -1))),
                window.settings.get("zigzag.width", ""), window.settings.get("zigzag.thickness", ""));
    }

    /** Sets the fields of the turn and the wrap as they were left, without planning them. */
    void restoreOtherParameters() {
        Job.Turn demo = Job.Turn.DEMO;
        window.parameters.angle.setText(window.settings.get("turn.angle", demo.angle()));
        window.parameters.overhang.setText(window.settings.get("turn.overhang", demo.overhang()));
        window.parameters.turnWidth.setText(window.settings.get("turn.width", demo.width()));
        window.parameters.turnThickness.setText(window.settings.get("turn.thickness", ""));
        window.parameters.wrapWidth.setText(window.settings.get("wrap.width", ""));
        window.parameters.wrapThickness.setText(window.settings.get("wrap.thickness", ""));
        window.parameters.wrapMaxFaces.setText(window.settings.get("wrap.maxFaces", ""));
        window.parameters.scriptMaxFaces.setText(window.settings.get("script.maxFaces", ""));
        window.parameters.wrapStrict.setSelected(Boolean.parseBoolean(window.settings.get("wrap.strict", "false")));
        window.parameters.wrapMethod.setSelectedIndex(
                window.settings.get("wrap.method", "zigzag").equals(ifold.wrap.Wrap.Method.HINGE.word()) ? 1 : 0);
        window.parameters.viewShow.setSelectedIndex(enumIndex(Scenes.Show.values(), window.settings.get("view.show", Scenes.Show.PATH.name())));
        window.parameters.viewColours.setSelectedIndex(enumIndex(PathView.Colors.values(), window.settings.get("view.colors", PathView.Colors.DARKNESS.name())));
        window.parameters.viewStrict.setSelected(Boolean.parseBoolean(window.settings.get("view.strict", "false")));
    }

    /** The index of the constant named {@code name}; the first for a name no longer known (a settings file edited or older). */
    static int enumIndex(Enum<?>[] constants, String name) {
        for (Enum<?> constant : constants) {
            if (constant.name().equals(name)) {
                return constant.ordinal();
            }
        }
        return 0;
    }

    static int clampCorner(int corner, int fallback) {
        return corner >= 0 && corner <= 2 ? corner : fallback;
    }

    void saveSettings() {
        window.settings.putInt("window.width", window.getWidth());
        window.settings.putInt("window.height", window.getHeight());
        window.settings.putInt("window.x", window.getX());
        window.settings.putInt("window.y", window.getY());
        try {
            window.settings.save();
        } catch (IOException e) {
            // Settings are a convenience: the window closes all the same.
            System.err.println("ifold: cannot save the settings to " + window.settings.file() + ": " + e.getMessage());
        }
    }
}
