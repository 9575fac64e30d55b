package ifold.job;

import ifold.mesh.PolygonSoup;
import ifold.mesh.io.MeshWriters;
import java.io.IOException;
import java.nio.file.Path;

/**
 * A built-in model made and written, as {@code ifold generate} and the window's New model both
 * make it ({@link BuiltInModels}): whole or not at all, a stop looked for while it is written.
 */
public final class GenerateJob {
    private GenerateJob() {
    }

    /**
     * What to make and where.
     *
     * @param around the torus's segments around the ring
     * @param across the torus's segments around the tube
     * @param subdivisions the times each of the icosphere's triangles is cut in four
     * @param grid a polycube's sides, cubes and seed
     * @param output the file (.off, .obj, .ply or .stl)
     * @param ascii PLY and STL as text rather than binary
     */
    public record Request(BuiltInModels.Shape shape, int around, int across, int subdivisions, BuiltInModels.Grid grid, Path output,
            boolean ascii) {
        /** A shape that is no polycube, or one of the defaults. */
        public Request(BuiltInModels.Shape shape, int around, int across, int subdivisions, Path output, boolean ascii) {
            this(shape, around, across, subdivisions, BuiltInModels.Grid.DEFAULT, output, ascii);
        }
    }

    /** A model made: its file and counts. */
    public record Made(Path file, int vertices, int faces) {
    }

    /**
     * Makes and writes the model.
     *
     * @throws ifold.geom.ParameterException where a count does not fit the shape
     * @throws IOException where the file cannot be written (nothing is left of it)
     * @throws java.util.concurrent.CancellationException once the watcher says stop
     */
    public static Made run(Request request, JobWatcher watcher) throws IOException {
        watcher.stage("making the " + request.shape());
        PolygonSoup soup = BuiltInModels.make(request.shape(), request.around(), request.across(), request.subdivisions(), request.grid());
        watcher.stopIfAsked();
        watcher.stage("writing " + request.output().getFileName());
        MeshWriters.write(new CancellableMesh(soup, watcher), request.output(), request.ascii());
        return new Made(request.output(), soup.vertexCount(), soup.faceCount());
    }
}
