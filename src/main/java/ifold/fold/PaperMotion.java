package ifold.fold;

/** A change of a paper that can be shown part of the way: a fold swinging, layers pressed together. */
public interface PaperMotion {
    /** The paper {@code fraction} of the way (0 = before, 1 = done). */
    Paper at(double fraction);
}
