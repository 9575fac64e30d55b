package ifold.job;

import ifold.mesh.PolygonSoup;
import ifold.mesh.Polycubes;
import ifold.mesh.Solids;
import ifold.geom.ParameterException;
import java.util.List;
import java.util.Locale;

/**
 * The models iFold makes itself ({@code ifold generate}, and the window's New model): the
 * solids in {@code models/}, an icosphere and a torus of any fineness. The shapes' parameters
 * are checked here, so that the command line and the window refuse the same values with the
 * same words.
 */
public final class BuiltInModels {
    /** The torus's segments around the ring and around the tube, unless given. */
    public static final int DEFAULT_AROUND = 24;
    public static final int DEFAULT_ACROSS = 12;
    /** The icosphere's subdivisions unless given: 1,280 triangles. */
    public static final int DEFAULT_SUBDIVISIONS = 3;
    /** The most subdivisions: 8 is 655,360 triangles, and each more is four times as many. */
    public static final int MAX_SUBDIVISIONS = 8;
    /** The most quads a torus may have: 100 million triangles, more than a heap of a few GB holds. */
    public static final long MAX_TORUS_SEGMENTS = 50_000_000L;
    /**
     * The name of the torus's two segment counts in a {@link ParameterException}: they are
     * refused together ({@code options --around and --across}), since their product is the limit.
     */
    public static final String SEGMENTS = "segments";

    /**
     * The shapes, named as the command line takes them ({@code ifold generate cube}): picocli
     * lists and matches an enum by its constants' names, hence lower case.
     */
    public enum Shape { tetrahedron, cube, octahedron, icosahedron, icosphere, torus, triangle, figure3, box, l, t, plus, staircase, polycube }

    /** The most cubes of a random polycube: each cube grown checks the whole surface, so n cubes cost n² squares. */
    public static final int MOST_RANDOM_CUBES = 5_000;

    /**
     * A polycube's parameters: a box's sides in cubes (a × b × c), and a random polycube's cubes
     * and the seed that grows it.
     */
    public record Grid(int[] size, int cubes, long seed) {
        /** A 2 × 1 × 1 box; 50 cubes from seed 1. */
        public static final Grid DEFAULT = new Grid(new int[] {2, 1, 1}, 50, 1);
    }

    private BuiltInModels() {
    }

    /**
     * Refuses parameters the shape cannot be made with; those a shape does not use are not
     * looked at.
     *
     * @param around the torus's segments around the ring
     * @param across the torus's segments around the tube
     * @param subdivisions the times each of the icosphere's triangles is cut in four
     * @throws ParameterException naming {@link #SEGMENTS} (the torus) or {@code subdivisions}
     */
    public static void check(Shape shape, int around, int across, int subdivisions) {
        check(shape, around, across, subdivisions, Grid.DEFAULT);
    }

    /**
     * As {@link #check(Shape, int, int, int)}, and a polycube's {@code grid}.
     *
     * @throws ParameterException naming {@code size} (a box), or {@code cubes} (a random polycube)
     */
    public static void check(Shape shape, int around, int across, int subdivisions, Grid grid) {
        if (shape == Shape.box) {
            int[] size = grid.size();
            if (size.length != 3 || size[0] < 1 || size[1] < 1 || size[2] < 1
                    || (long) size[0] * size[1] * size[2] > ifold.mesh.Polycubes.MOST_CUBES) {
                throw new ParameterException("size", "must be three whole numbers AxBxC, each at least 1, at most "
                        + ifold.mesh.Polycubes.MOST_CUBES + " cubes in all");
            }
        }
        if (shape == Shape.polycube && (grid.cubes() < 1 || grid.cubes() > MOST_RANDOM_CUBES)) {
            throw new ParameterException("cubes", "must be 1 to " + MOST_RANDOM_CUBES + ", got " + grid.cubes());
        }
        checkCounts(shape, around, across, subdivisions);
    }

    private static void checkCounts(Shape shape, int around, int across, int subdivisions) {
        if (shape == Shape.torus && (around < 3 || across < 3 || (long) around * across > MAX_TORUS_SEGMENTS)) {
            throw new ParameterException(SEGMENTS, "each must be at least 3, and their product at most " + MAX_TORUS_SEGMENTS);
        }
        if (shape == Shape.icosphere && (subdivisions < 0 || subdivisions > MAX_SUBDIVISIONS)) {
            throw new ParameterException("subdivisions", "must be 0 to " + MAX_SUBDIVISIONS + ", got " + subdivisions);
        }
    }

    /**
     * Makes the shape (a torus of ring radius 3 and tube radius 1).
     *
     * @throws ParameterException as {@link #check} does
     */
    public static PolygonSoup make(Shape shape, int around, int across, int subdivisions) {
        return make(shape, around, across, subdivisions, Grid.DEFAULT);
    }

    /**
     * As {@link #make(Shape, int, int, int)}; a polycube's squares from {@code grid}: a box of
     * unit cubes, the L (four cubes), the T (four), the plus (five), a staircase of three steps
     * (six), or {@code grid.cubes()} grown at random from {@code grid.seed()}, its surface a sphere.
     */
    public static PolygonSoup make(Shape shape, int around, int across, int subdivisions, Grid grid) {
        check(shape, around, across, subdivisions, grid);
        return switch (shape) {
            case box -> Polycubes.surface(Polycubes.box(grid.size()[0], grid.size()[1], grid.size()[2]));
            case l -> Polycubes.surface(Polycubes.l());
            case t -> Polycubes.surface(Polycubes.t());
            case plus -> Polycubes.surface(Polycubes.plus());
            case staircase -> Polycubes.surface(Polycubes.staircase());
            case polycube -> Polycubes.surface(Polycubes.random(grid.cubes(), grid.seed()));
            case tetrahedron -> Solids.tetrahedron();
            case cube -> Solids.cube();
            case octahedron -> Solids.octahedron();
            case icosahedron -> Solids.icosahedron();
            case icosphere -> Solids.icosphere(subdivisions);
            case torus -> Solids.torus(3, 1, around, across);
            case triangle -> Solids.triangle();
            case figure3 -> Solids.figure3();
        };
    }

    /**
     * The parameters {@code shape} takes, as the requests name them ({@code around}, {@code
     * across}, {@code subdivisions}, {@code size}, {@code cubes}, {@code seed}); none for a
     * fixed shape.
     */
    public static List<String> parametersOf(Shape shape) {
        return switch (shape) {
            case torus -> List.of("around", "across");
            case icosphere -> List.of("subdivisions");
            case box -> List.of("size");
            case polycube -> List.of("cubes", "seed");
            case tetrahedron, cube, octahedron, icosahedron, triangle, figure3, l, t, plus, staircase -> List.of();
        };
    }

    /** A file name for the shape: {@code torus-24x12}, {@code icosphere-3}, {@code cube}. */
    public static String name(Shape shape, int around, int across, int subdivisions) {
        return name(shape, around, across, subdivisions, Grid.DEFAULT);
    }

    /** As {@link #name(Shape, int, int, int)}: {@code box-3x2x1}, {@code polycube-50-seed1}. */
    public static String name(Shape shape, int around, int across, int subdivisions, Grid grid) {
        return switch (shape) {
            case torus -> String.format(Locale.ROOT, "torus-%dx%d", around, across);
            case icosphere -> "icosphere-" + subdivisions;
            case box -> String.format(Locale.ROOT, "box-%dx%dx%d", grid.size()[0], grid.size()[1], grid.size()[2]);
            case polycube -> String.format(Locale.ROOT, "polycube-%d-seed%d", grid.cubes(), grid.seed());
            default -> shape.name();
        };
    }
}
