package ifold.job;

import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.geom.ParameterException;
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
    public enum Shape { tetrahedron, cube, octahedron, icosahedron, icosphere, torus, triangle, figure3 }

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
        check(shape, around, across, subdivisions);
        return switch (shape) {
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

    /** A file name for the shape: {@code torus-24x12}, {@code icosphere-3}, {@code cube}. */
    public static String name(Shape shape, int around, int across, int subdivisions) {
        return switch (shape) {
            case torus -> String.format(Locale.ROOT, "torus-%dx%d", around, across);
            case icosphere -> "icosphere-" + subdivisions;
            default -> shape.name();
        };
    }
}
