package ifold.script;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.joml.Vector3d;

/**
 * A sheet of paper and the folds to make on it, in order. Each fold's line may be given in 3D
 * or in the paper coordinates of the top layer; the latter are placed on the paper as it is
 * when the fold comes.
 *
 * <p>The text format, one statement a line, {@code #} to the end of a line is a comment:
 * <pre>
 * paper strip LENGTH WIDTH | paper square SIDE | paper rectangle WIDTH HEIGHT
 * thickness T
 * fold valley|mountain DEGREES LINE left|right
 *   LINE = paper U1 V1 U2 V2 | flap U1 V1 U2 V2 | points X1 Y1 Z1 X2 Y2 Z2 | point X Y Z direction DX DY DZ
 * </pre>
 * {@code left} or {@code right} is the side that moves, seen from the paper's top with the line
 * running from its first point to its second.
 */
public final class FoldScript {
    private final double width;
    private final double height;
    private final double thickness;
    private final List<Step> steps;

    private FoldScript(double width, double height, double thickness, List<Step> steps) {
        this.width = width;
        this.height = height;
        this.thickness = thickness;
        this.steps = List.copyOf(steps);
    }

    /** Valley: the moving paper turns up, towards the normal of the plane it lies in; mountain: down. */
    public enum Kind { VALLEY, MOUNTAIN }

    /** The side of the line that moves, seen from the paper's top (the plane's normal) with the line running from its first point to its second. */
    public enum Side { LEFT, RIGHT }

    /**
     * One fold of a script.
     *
     * @param kind valley or mountain
     * @param degrees the angle
     * @param onPaper whether the line's points are paper coordinates (u, v) rather than 3D
     * @param flap whether only the flap beyond the line (on the sheet) moves, rather than every
     *     layer on that side in space; the line is then on paper
     * @param from the line's first point (u, v, 0 on paper)
     * @param to the line's second point
     * @param moving the side that moves
     * @param line the script line, or 0
     */
    public record Step(Kind kind, double degrees, boolean onPaper, boolean flap, Vector3d from, Vector3d to, Side moving, int line) {
    }

    /** The sheet's length: its extent along u (x on the table). */
    public double length() {
        return width;
    }

    /** The sheet's width: its extent along v (y on the table). */
    public double width() {
        return height;
    }

    public double thickness() {
        return thickness;
    }

    public List<Step> steps() {
        return steps;
    }

    /** The same folds on paper of another thickness (0 for ideal paper). */
    public FoldScript withThickness(double t) {
        return new FoldScript(width, height, t, steps);
    }

    /** Every fold of the script made in turn on the sheet engine. */
    public ScriptFolding.Result play() throws FoldScriptException {
        return play(new long[steps.size()]);
    }

    /** Like {@link #play()}, writing the nanoseconds each fold took to {@code nanosPerFold}. */
    public ScriptFolding.Result play(long[] nanosPerFold) throws FoldScriptException {
        return ScriptFolding.play(this, nanosPerFold, ScriptFolding.DEFAULT_MAX_FACES);
    }

    /** Like {@link #play(long[])}, with at most {@code maxFaces} faces of paper. */
    public ScriptFolding.Result play(long[] nanosPerFold, int maxFaces) throws FoldScriptException {
        return ScriptFolding.play(this, nanosPerFold, maxFaces);
    }

    /** Like {@link #play(long[], int)}, telling {@code after} the paper as it stands after each fold. */
    public ScriptFolding.Result play(long[] nanosPerFold, int maxFaces, ScriptFolding.AfterFold after) throws FoldScriptException {
        return ScriptFolding.play(this, nanosPerFold, maxFaces, after);
    }

    private static String fmt(double value) {
        // Whole numbers without ".0"; beyond a long's range, as doubles are written.
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value) : Double.toString(value);
    }

    public static Builder builder() {
        return new Builder();
    }

    /** Builds a script in code: {@code FoldScript.builder().strip(20, 1).thickness(0.01).valleyOnPaper(...).build()}. */
    public static final class Builder {
        private double width = -1;
        private double height = -1;
        private double thickness = 0.01;
        private final List<Step> steps = new ArrayList<>();

        public Builder rectangle(double w, double h) {
            width = w;
            height = h;
            return this;
        }

        public Builder strip(double length, double w) {
            return rectangle(length, w);
        }

        public Builder square(double side) {
            return rectangle(side, side);
        }

        public Builder thickness(double t) {
            thickness = t;
            return this;
        }

        /** A fold along the line through two paper points (u, v). */
        public Builder foldOnPaper(Kind kind, double degrees, double u1, double v1, double u2, double v2, Side moving) {
            steps.add(new Step(kind, degrees, true, false, new Vector3d(u1, v1, 0), new Vector3d(u2, v2, 0), moving, 0));
            return this;
        }

        /** A flap fold: only the paper beyond the line through two paper points (u, v), on the sheet, turns. */
        public Builder flap(Kind kind, double degrees, double u1, double v1, double u2, double v2, Side moving) {
            steps.add(new Step(kind, degrees, true, true, new Vector3d(u1, v1, 0), new Vector3d(u2, v2, 0), moving, 0));
            return this;
        }

        /** A fold along the line through two 3D points. */
        public Builder fold(Kind kind, double degrees, Vector3d from, Vector3d to, Side moving) {
            steps.add(new Step(kind, degrees, false, false, new Vector3d(from), new Vector3d(to), moving, 0));
            return this;
        }

        Builder add(Step step) {
            steps.add(step);
            return this;
        }

        public FoldScript build() {
            if (!(width > 0) || !(height > 0)) {
                throw new IllegalArgumentException("a script needs a paper with a positive size");
            }
            return new FoldScript(width, height, thickness, steps);
        }
    }

    /** Reads a script file; errors name the line. */
    public static FoldScript read(Path file) throws IOException, FoldScriptException {
        byte[] bytes = Files.readAllBytes(file);
        for (byte b : bytes) {
            if (b == 0) {
                throw new FoldScriptException(0, "binary content, expected a text fold script");
            }
        }
        String text = new String(bytes, StandardCharsets.UTF_8);
        // A byte order mark, as editors on Windows write one, is no statement.
        return parse(text.startsWith("\ufeff") ? text.substring(1) : text);
    }

    /** Parses the text format (see the class documentation). */
    public static FoldScript parse(String text) throws FoldScriptException {
        Builder builder = new Builder();
        boolean paperSeen = false;
        String[] lines = text.split("\r\n|\r|\n", -1);
        for (int i = 0; i < lines.length; i++) {
            int number = i + 1;
            String line = lines[i];
            int hash = line.indexOf('#');
            if (hash >= 0) {
                line = line.substring(0, hash);
            }
            line = line.strip();
            if (line.isEmpty()) {
                continue;
            }
            Tokens tokens = new Tokens(line.split("\\s+"), number);
            String keyword = tokens.word("a statement");
            switch (keyword) {
                case "paper" -> {
                    if (paperSeen) {
                        throw new FoldScriptException(number, "a second 'paper': a script folds one sheet");
                    }
                    if (!builder.steps.isEmpty()) {
                        throw new FoldScriptException(number, "'paper' must come before the folds");
                    }
                    String shape = tokens.word("strip, square or rectangle");
                    switch (shape) {
                        case "strip", "rectangle" -> builder.rectangle(tokens.positive("the length"), tokens.positive("the width"));
                        case "square" -> builder.square(tokens.positive("the side"));
                        default -> throw new FoldScriptException(number, "unknown paper '" + shape + "': expected strip, square or rectangle");
                    }
                    paperSeen = true;
                }
                case "thickness" -> {
                    double t = tokens.number("the thickness");
                    if (!(t >= 0)) {
                        throw new FoldScriptException(number, "the thickness must be zero or more, got " + t);
                    }
                    builder.thickness(t);
                }
                case "fold" -> {
                    if (!paperSeen) {
                        throw new FoldScriptException(number, "a fold before any 'paper'");
                    }
                    builder.add(parseFold(tokens, number));
                }
                default -> throw new FoldScriptException(number, "unknown statement '" + keyword + "': expected paper, thickness or fold");
            }
            tokens.end();
        }
        if (!paperSeen) {
            throw new FoldScriptException(0, "no 'paper' statement: say which sheet to fold, e.g. 'paper strip 20 1'");
        }
        return builder.build();
    }

    private static Step parseFold(Tokens tokens, int number) throws FoldScriptException {
        String kindWord = tokens.word("valley or mountain");
        Kind kind = switch (kindWord) {
            case "valley" -> Kind.VALLEY;
            case "mountain" -> Kind.MOUNTAIN;
            default -> throw new FoldScriptException(number, "'" + kindWord + "': expected valley or mountain");
        };
        double degrees = tokens.number("the angle in degrees");
        if (!(degrees > 0 && degrees <= 180)) {
            throw new FoldScriptException(number, "the angle must be more than 0 and at most 180 degrees, got " + fmt(degrees));
        }
        String form = tokens.word("paper, flap, points or point");
        boolean onPaper;
        boolean flap = false;
        Vector3d from;
        Vector3d to;
        switch (form) {
            case "paper", "flap" -> {
                onPaper = true;
                flap = form.equals("flap");
                from = new Vector3d(tokens.number("u1"), tokens.number("v1"), 0);
                to = new Vector3d(tokens.number("u2"), tokens.number("v2"), 0);
            }
            case "points" -> {
                onPaper = false;
                from = new Vector3d(tokens.number("x1"), tokens.number("y1"), tokens.number("z1"));
                to = new Vector3d(tokens.number("x2"), tokens.number("y2"), tokens.number("z2"));
            }
            case "point" -> {
                onPaper = false;
                from = new Vector3d(tokens.number("x"), tokens.number("y"), tokens.number("z"));
                tokens.expect("direction");
                to = new Vector3d(tokens.number("dx"), tokens.number("dy"), tokens.number("dz")).add(from);
            }
            default -> throw new FoldScriptException(number, "'" + form + "': expected paper, flap, points or point to give the line");
        }
        if (from.distance(to) == 0) {
            throw new FoldScriptException(number, "the line's two points are the same: a line needs a direction");
        }
        String sideWord = tokens.word("left or right (the side that moves)");
        Side side = switch (sideWord) {
            case "left" -> Side.LEFT;
            case "right" -> Side.RIGHT;
            default -> throw new FoldScriptException(number, "'" + sideWord + "': expected left or right (the side that moves)");
        };
        return new Step(kind, degrees, onPaper, flap, from, to, side, number);
    }

    /** The words of one line, read in order, with errors that name the line and what was expected. */
    private static final class Tokens {
        private final String[] words;
        private final int line;
        private int next;

        Tokens(String[] words, int line) {
            this.words = words;
            this.line = line;
        }

        String word(String expected) throws FoldScriptException {
            if (next >= words.length) {
                throw new FoldScriptException(line, "missing " + expected);
            }
            return words[next++].toLowerCase(Locale.ROOT);
        }

        void expect(String keyword) throws FoldScriptException {
            String word = word("'" + keyword + "'");
            if (!word.equals(keyword)) {
                throw new FoldScriptException(line, "'" + word + "': expected '" + keyword + "'");
            }
        }

        double number(String expected) throws FoldScriptException {
            String word = word(expected);
            try {
                double value = Double.parseDouble(word);
                if (!Double.isFinite(value)) {
                    throw new NumberFormatException();
                }
                return value;
            } catch (NumberFormatException e) {
                throw new FoldScriptException(line, "'" + word + "' is not a number (" + expected + ")");
            }
        }

        double positive(String expected) throws FoldScriptException {
            double value = number(expected);
            if (!(value > 0)) {
                throw new FoldScriptException(line, expected + " must be positive, got " + fmt(value));
            }
            return value;
        }

        void end() throws FoldScriptException {
            if (next < words.length) {
                throw new FoldScriptException(line, "unexpected '" + words[next] + "' at the end of the statement");
            }
        }
    }
}
