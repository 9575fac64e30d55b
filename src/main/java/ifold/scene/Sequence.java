package ifold.scene;

import java.util.List;

/**
 * Animations played one after the other: positions run through the first's steps, then the
 * second's. Applying a position sets every part: those before it at their end, those after at
 * their start, so stepping backwards restores the scene.
 */
public final class Sequence implements Animation {
    private final List<Animation> parts;

    public Sequence(List<Animation> parts) {
        if (parts.isEmpty()) {
            throw new IllegalArgumentException("a sequence needs at least one animation");
        }
        this.parts = List.copyOf(parts);
    }

    @Override
    public int stepCount() {
        int steps = 0;
        for (Animation part : parts) {
            steps += part.stepCount();
        }
        return steps;
    }

    @Override
    public void apply(double position) {
        double offset = 0;
        for (Animation part : parts) {
            int steps = part.stepCount();
            part.apply(Math.max(0, Math.min(steps, position - offset)));
            offset += steps;
        }
    }

    @Override
    public String describe(double position) {
        double offset = 0;
        for (int i = 0; i < parts.size(); i++) {
            Animation part = parts.get(i);
            int steps = part.stepCount();
            if (position < offset + steps || i == parts.size() - 1) {
                return part.describe(Math.max(0, Math.min(steps, position - offset)));
            }
            offset += steps;
        }
        return "";
    }
}
