package ifold.job;

import ifold.mesh.GridSquares;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.SelfCrossings;
import ifold.refine.HamiltonianRefinement;
import ifold.wrap.HingeStrip;
import ifold.wrap.HingeTour;
import ifold.wrap.PlacedWrap;
import ifold.wrap.Seam;
import ifold.wrap.Wrap;
import ifold.wrap.WrapAnalysis;
import ifold.wrap.PaperInSpace;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * The wrap of a model file, as {@code ifold wrap} and the window's Wrap the model both do it: the
 * model read and built, moved near its centre where it lies far out, its faces prepared and
 * refined, wrapped, placed in space and analysed, and the figures of its report. One pipeline:
 * the front ends read what the user asked, run it, and present what it returns (each then
 * writes and checks its outputs, and says a failure in its own words).
 */
public final class WrapJob {
    private WrapJob() {
    }

    /** What to wrap and how: the model file, how strictly it is built, the strip, the method. */
    public record Request(Path model, MeshBuilder.Options build, Wrap.Options options, Wrap.Method method) {
        /** The zig-zag's wrap. */
        public Request(Path model, MeshBuilder.Options build, Wrap.Options options) {
            this(model, build, options, Wrap.Method.ZIGZAG);
        }
    }

    /**
     * What a wrap tells as it goes, besides the triangles wrapped and whether to stop: the
     * stage it starts, and notes on the data a user should read before the result (a repair
     * made, the model moved near its centre, faces kept as they are).
     */
    public interface Watcher extends Wrap.Watcher {
        /** A stage begins: "reading cube.off", "refining 12 triangles", "wrapping 58 triangles", "analysing". */
        default void stage(String what) {
        }

        /** A note on the model, in one line without a prefix: "models/x.off: repaired: dropped 1 zero-area face". */
        default void note(String line) {
        }
    }

    /**
     * A wrap done.
     *
     * @param loaded the model as read and built, with its repairs
     * @param mesh the model's mesh, moved by {@code movedBy}
     * @param movedBy what was taken from every coordinate (zeros where the model was left where it lies)
     * @param path the prepared and refined path the strip follows
     * @param figures the report's figures: {@link Reports#wrap}, and {@code movedBy} where moved
     * @param seconds the phases' times: load, refine, wrap, analyse
     */
    public record Outcome(ModelFiles.Loaded loaded, HalfedgeMesh mesh, double[] movedBy, WrapPath path, Wrap.Result result,
            List<PaperInSpace> geometries, WrapAnalysis analysis, Map<String, Object> figures, Seconds seconds) {
        /** The zig-zag's refinement; null for the hinge strip. */
        public HamiltonianRefinement.Result refinement() {
            return path.refinement();
        }
    }

    /** How long each phase took, in seconds. */
    public record Seconds(double load, double refine, double wrap, double analyse) {
    }

    /**
     * The model cannot be wrapped as it is, for what it is, not for the wrap's options: its
     * surface runs through itself, or the paper came out stretched (rounding at the model's
     * coordinates is coarser than its folds). A failure of the data, not of the wrap's code.
     */
    public static final class Refused extends Exception {
        private static final long serialVersionUID = 1L;

        Refused(String message) {
            super(message);
        }
    }

    /**
     * Runs the wrap.
     *
     * @throws ModelFiles.LoadFailure where the file cannot be read or built, or holds no faces after its repairs
     * @throws Wrap.WrapException where the wrap refuses (a {@link Wrap.FaceLimitException} or
     *     {@link Wrap.TooWideException} names the option to change)
     * @throws ifold.geom.ParameterException where a value given does not fit this model
     * @throws Refused where the model's surface runs through itself, or the paper came out stretched
     * @throws java.util.concurrent.CancellationException once the watcher says stop
     */
    public static Outcome run(Request request, Watcher watcher) throws ModelFiles.LoadFailure, Wrap.WrapException, Refused {
        Path model = request.model();
        long started = System.nanoTime();
        watcher.stage("reading " + model.getFileName());
        ModelFiles.Loaded loaded = ModelFiles.load(model, request.build());
        String noFaces = loaded.noFacesLeft(model, "nothing to wrap");
        if (noFaces != null) {
            throw new ModelFiles.LoadFailure(noFaces, false);
        }
        for (String note : ModelFiles.repairNotes(model, loaded.repairs())) {
            watcher.note(note);
        }
        HalfedgeMesh mesh = loaded.built().mesh();
        if (mesh.faceCount() == 0) {
            throw new ModelFiles.LoadFailure(model + ": no faces left to wrap", false);
        }
        stopIfAsked(watcher);
        double[] movedBy = NearOrigin.move(mesh);
        if (NearOrigin.moved(movedBy)) {
            watcher.note(model + ": wrapped about " + Reports.point(movedBy) + ", near its centre, where doubles can hold"
                    + " the paper: the exports' coordinates are about that point");
        }
        watcher.stage("checking the surface of " + mesh.faceCount() + " triangles");
        stopIfAsked(watcher);
        int[] crossing = SelfCrossings.first(mesh);
        stopIfAsked(watcher);
        if (crossing != null) {
            // Paper laid on it would pass through itself, or cover one place twice: refused rather
            // than wrapped into paper whose layers cannot be ordered (a cube with one corner of a
            // face wrong wrapped "valid" with 2,464 violations of its layer order, exit 0).
            throw new Refused("the model's surface runs through itself: the triangles (" + Wrap.cornersText(mesh, crossing[0]) + ") and ("
                    + Wrap.cornersText(mesh, crossing[1]) + ") cross or overlap, and paper laid on them would too; repair the model");
        }
        long loadedAt = System.nanoTime();
        WrapPath path;
        long refinedAt;
        Wrap.Result result;
        Seam.Chosen seam = null;
        Map<String, Object> otherTried = null; // the other path's wrap, where it was tried
        if (request.method() == Wrap.Method.HINGE) {
            watcher.stage("finding the squares of " + mesh.faceCount() + " triangles");
            path = hingePath(model, mesh, request.options());
            refinedAt = System.nanoTime();
            watcher.stage("wrapping " + path.squares().count() + " squares");
            result = HingeStrip.wrap(path.squares(), path.tour(), thickness(request.options(), path.squares().spacing()),
                    request.options().maxFaces(), watcher);
        } else {
            watcher.stage("preparing and refining " + mesh.faceCount() + " triangles");
            path = WrapPath.of(mesh);
            String kept = path.keptNote(model.toString());
            if (kept != null) {
                watcher.note(kept);
            }
            stopIfAsked(watcher);
            // A big model's path along its own triangles, asked once: the width's bound, the stage and the seam need it.
            HamiltonianRefinement.Result instead = Seam.ownInstead(path.refinement(), request.options());
            String tooWide = widerThanSound(path.refinement(), instead, request.options());
            if (tooWide != null) {
                throw new Wrap.TooWideException(tooWide);
            }
            refinedAt = System.nanoTime();
            int tries = Seam.tries(path.refinement(), request.options().width());
            watcher.stage(instead != null ? "wrapping the model's own " + instead.mesh().faceCount() + " triangles"
                    : "wrapping " + path.refinement().mesh().faceCount() + " triangles"
                    + (tries > 1 ? ", begun at " + tries + " places round the path" : ""));
            // Of the starts tried, one whose paper the independent checker finds colliding is kept
            // only where all collide.
            seam = Seam.wrap(path.refinement(), instead, request.options(), watcher, Collisions.OF_SEAM);
            // A small model whose most layers pile where thin triangles fan in a plane (a cone's
            // base, 32 about its centre) is wrapped along the prepared faces too, and the better
            // kept as the seam keeps the better start: the path likely to make fewer faces made
            // 64 layers there, the prepared 37.
            WrapAnalysis.Deepest deepest = seam.placed().analysis().deepest();
            WrapPath other = instead == null && mesh.faceCount() <= Seam.MOST_TRIANGLES && deepest != null
                    && path.fanNear(deepest.point(), FAN_REACH * seam.result().width()) ? path.other() : null;
            if (other != null) {
                watcher.stage("wrapping the " + (other.prepared() ? "prepared faces' " : "model's own ") + other.refinement().mesh().faceCount()
                        + " triangles too");
                otherTried = new java.util.LinkedHashMap<>();
                otherTried.put("prepared", other.prepared());
                try {
                    Seam.Chosen otherSeam = Seam.wrap(other.refinement(), null, request.options(), Seam.stoppedBy(watcher), Collisions.OF_SEAM);
                    boolean better = otherSeam.betterThan(seam);
                    otherTried.put("layers", otherSeam.maxLayers());
                    otherTried.put("collisions", otherSeam.collisions());
                    otherTried.put("kept", better);
                    otherTried.put("firstLayers", seam.maxLayers());
                    otherTried.put("firstCollisions", seam.collisions());
                    if (better) {
                        seam = otherSeam;
                        path = other;
                    }
                } catch (Wrap.WrapException e) {
                    stopIfAsked(watcher); // the other path refused: the first stands
                    otherTried.put("refused", e.getMessage());
                } catch (ifold.geom.ParameterException e) {
                    if (!"thickness".equals(e.parameter())) {
                        throw e;
                    }
                    otherTried.put("refused", e.getMessage()); // too thick for its narrower strip: the first stands
                }
            }
            String passedOver = passedOver(model.toString(), seam);
            if (passedOver != null) {
                watcher.note(passedOver);
            }
            path = new WrapPath(path.preparation(), seam.refinement(), path.prepared());
            result = seam.result();
            String widened = widened(model.toString(), path.refinement(), request.options(), result);
            if (widened != null) {
                watcher.note(widened);
            }
        }
        long wrappedAt = System.nanoTime();
        stopIfAsked(watcher);
        watcher.stage("analysing");
        // The seam's tries each took their measures already: the one kept has its own.
        PlacedWrap placed = seam != null ? seam.placed() : PlacedWrap.of(result);
        WrapAnalysis analysis = placed.analysis();
        String stretched = Reports.stretched(analysis);
        if (stretched != null) {
            throw new Refused(stretched);
        }
        Map<String, Object> figures = Reports.wrap(model.toString(), mesh.faceCount(), loaded.repairs(), path, result, analysis);
        if (seam != null && (!seam.layersTried().isEmpty() || !seam.ownLayersTried().isEmpty())) {
            Map<String, Object> begun = new java.util.LinkedHashMap<>();
            begun.put("along", seam.along());
            begun.put("layersTried", seam.layersTried());
            begun.put("collisionsTried", seam.collisionsTried());
            if (!seam.ownLayersTried().isEmpty()) {
                begun.put("ownLayersTried", seam.ownLayersTried());
                begun.put("ownCollisionsTried", seam.ownCollisionsTried());
            }
            figures.put("seam", begun);
        }
        if (otherTried != null) {
            figures.put("otherPath", otherTried);
        }
        if (NearOrigin.moved(movedBy)) {
            figures.put("movedBy", List.of(movedBy[0], movedBy[1], movedBy[2]));
        }
        long analysedAt = System.nanoTime();
        // The kept start's paper was placed and measured as it was tried: its time is the analysis's.
        double measured = seam != null ? seam.measureSeconds() : 0;
        return new Outcome(loaded, mesh, movedBy, path, result, placed.geometries(), analysis, figures,
                new Seconds((loadedAt - started) * 1e-9, (refinedAt - loadedAt) * 1e-9, (wrappedAt - refinedAt) * 1e-9 - measured,
                        (analysedAt - wrappedAt) * 1e-9 + measured));
    }

    /**
     * Why a strip {@code width} wide is refused though the path takes it, or null where it is not:
     * wider than the default, a third of the widest. The engine folds strips up to the widest, but
     * their paper is sound only so far, as measured (2026-12-06, the 19 models of the comparison
     * set and the 320-triangle icosphere, each at the default, 0.4 and 0.5 of the widest): at
     * 0.4 the 576-triangle torus's layer order had 8 violations and 108 crossing pairs, at 0.5 the
     * dodecahedron, figure3 and the torus crossed themselves (2, 11 and 84 pairs), and from 0.6
     * the icosphere's (307 to 1,993 pairs); at the widest the cube, tetrahedron, octahedron and
     * icosahedron (24, 9, 59, 171). Wider strips lay the turns, gadgets, tucks and folds over
     * edges of neighbouring triangles at the hosts' corners (docs/wrap.md, Limits). A width over
     * the widest is left to the engine, which names the triangle it does not fit. Of the paths
     * tried, the model's own triangles' too: the seam's short one, or {@code instead}, a big
     * model's ({@code Seam.ownInstead}; null where there is none).
     */
    static String widerThanSound(HamiltonianRefinement.Result refinement, HamiltonianRefinement.Result instead, Wrap.Options options) {
        double width = options.width();
        if (Double.isNaN(width) || !Wrap.takesSize(refinement.mesh())) {
            return null; // the default, or a model the engine refuses for its size, saying so
        }
        double widest = Wrap.widest(refinement);
        double sound = Wrap.defaultWidth(refinement);
        // The seam also tries the path along the model's own triangles, whose default is wider.
        HamiltonianRefinement.Result own = Seam.ownPath(refinement, Double.NaN);
        if (own == null) {
            own = instead; // a big model's, where it is folded along them
        }
        if (own != null) {
            widest = Math.max(widest, Wrap.widest(own));
            sound = Math.max(sound, Wrap.defaultWidth(own));
        }
        if (!(width > sound * (1 + 1e-12)) || widest < width * (1 - 1e-12)) {
            return null;
        }
        return String.format(java.util.Locale.ROOT, "the strip width %s is wider than %s, a third of the widest strip the path"
                + " takes (%s): wider strips lay the turns and tucks of neighbouring triangles together at the corners of the"
                + " faces, where their paper crosses itself (docs/wrap.md, Limits); give --width %s or less", width, sound, widest,
                sound);
    }

    /**
     * Where the default strip was widened past a third of the widest to keep within the face
     * limit ({@code Wrap.fittingDefault}), one line saying so, naming {@code model}; null where it was not.
     */
    static String widened(String model, HamiltonianRefinement.Result path, Wrap.Options options, Wrap.Result result) {
        double third = Wrap.defaultWidth(path);
        if (!Double.isNaN(options.width()) || !(result.width() > third * (1 + 1e-9))) {
            return null;
        }
        return String.format(java.util.Locale.ROOT, "%s: the strip is %.4g wide, wider than the default third of the widest (%.4g), to keep"
                + " within the limit of %,d faces of paper (--max-faces raises it)", model,
                result.width(), third, options.maxFaces());
    }

    /**
     * Where the seam passed over a start with fewer layers than the one kept because its paper
     * collides, one line saying so, naming {@code model}; null where it did not. (The irregular
     * pentagonal pyramid of SeamTest, before its roll was mended: "begun where its paper is
     * sound: a start with 37 layers, not 54, was passed over, the collision check finding 63
     * collisions in its paper".)
     */
    static String passedOver(String model, Seam.Chosen seam) {
        int kept = seam.placed().analysis().maxLayers();
        int fewest = kept;
        int collisions = 0;
        for (int k = 0; k < seam.layersTried().size(); k++) {
            Integer layers = seam.layersTried().get(k);
            Integer found = seam.collisionsTried().get(k);
            if (layers != null && found != null && found > 0 && layers < fewest) {
                fewest = layers;
                collisions = found;
            }
        }
        return fewest < kept ? model + ": begun where its paper is sound: a start with " + fewest + " layers, not " + kept
                + ", was passed over, the collision check finding " + collisions + (collisions == 1 ? " collision" : " collisions")
                + " in its paper" : null;
    }

    /**
     * Where a zig-zag wrap's paper on a grid polyhedron was found to cross itself, the method
     * made for such models, in words ("cube.off: its paper crosses itself; ..."); else null. A
     * random polycube of 30 cubes crosses in 357 pairs, and the hinge strip lays two layers that
     * do not. Said by the command line and the window's check alike.
     */
    public static String hingeInstead(String model, ifold.mesh.IndexedPolygons mesh, Wrap.Method method, boolean collided) {
        if (method != Wrap.Method.ZIGZAG || !collided) {
            return null;
        }
        try {
            GridSquares.of(mesh, Double.NaN);
        } catch (GridSquares.NotGrid e) {
            return null;
        }
        return model + ": its paper crosses itself; it is a grid polyhedron, which the hinge strip wraps in two layers";
    }

    /**
     * The hinge strip's path: the model's squares, as wide as its lattice's unless a width is
     * given (which must divide it), and their tour.
     *
     * @throws Refused where the model is not a closed grid polyhedron
     */
    private static WrapPath hingePath(Path model, HalfedgeMesh mesh, Wrap.Options options) throws Refused {
        GridSquares squares;
        try {
            squares = GridSquares.of(mesh, Double.NaN);
            if (!Double.isNaN(options.width())) {
                double squaresAcross = squares.spacing() / options.width();
                if (!(Math.abs(squaresAcross - Math.rint(squaresAcross)) <= 1e-9 * squaresAcross) || Math.rint(squaresAcross) < 1) {
                    long whole = Math.max(1, Math.round(squaresAcross));
                    throw new ifold.geom.ParameterException("width", String.format(java.util.Locale.ROOT, "the hinge strip is as wide as the "
                            + "model's lattice square, %s, or that over a whole number (the nearest: %s, the square cut in %d); got %s", squares.spacing(),
                            squares.spacing() / whole, whole, options.width()));
                }
                double across = Math.rint(squaresAcross);
                if (squares.count() * across * across > GridSquares.MOST_SQUARES) {
                    throw new ifold.geom.ParameterException("width", String.format(java.util.Locale.ROOT, "a hinge strip %s wide cuts the "
                            + "surface into %.0f squares, more than %d: the narrowest it takes is %s", options.width(),
                            squares.count() * across * across, GridSquares.MOST_SQUARES,
                            squares.spacing() / Math.floor(Math.sqrt((double) GridSquares.MOST_SQUARES / squares.count()))));
                }
                squares = GridSquares.of(mesh, options.width());
            }
        } catch (GridSquares.NotGrid e) {
            throw new Refused(e.getMessage());
        }
        return WrapPath.hinge(squares, HingeTour.of(squares));
    }

    /** The thickness asked for, or the default for the width; at most a quarter of the width. */
    private static double thickness(Wrap.Options options, double width) {
        double thickness = Double.isNaN(options.thickness()) ? Wrap.defaultThickness(width) : options.thickness();
        if (thickness > width / 4) {
            throw new ifold.geom.ParameterException("thickness", "must be at most a quarter of the width " + ifold.geom.ParameterException.shown(width)
                    + ", got " + ifold.geom.ParameterException.shown(thickness));
        }
        return thickness;
    }

    /**
     * How near the deepest point, in widths of the strip, a fan of thin triangles in a plane is
     * taken for the cause of its layers ({@link WrapPath#fanNear}): the cone's deepest point lay
     * 0.1 widths from its base's centre.
     */
    static final double FAN_REACH = 2;

    private static void stopIfAsked(Watcher watcher) {
        if (watcher.stopped()) {
            throw new java.util.concurrent.CancellationException("stopped");
        }
    }
}
