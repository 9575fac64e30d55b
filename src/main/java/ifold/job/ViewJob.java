package ifold.job;

import ifold.mesh.Defect;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.refine.HamiltonianRefinement;
import ifold.scene.PathView;
import ifold.scene.Scene;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A model looked at, as {@code ifold view} and the window's View a model both show it: read and
 * built (triangulated where its refinement or path is shown), refined where asked, and put in a
 * scene ({@link Scenes#view}).
 */
public final class ViewJob {
    private ViewJob() {
    }

    /**
     * What to show.
     *
     * @param model the model file
     * @param strict refuse a defect the builder could repair
     * @param show the model, its refinement, or the path growing along it
     * @param colors how the path colours its triangles
     */
    public record Request(Path model, boolean strict, Scenes.Show show, PathView.Colors colors) {
    }

    /**
     * A model shown.
     *
     * @param request what was asked
     * @param mesh the model's mesh
     * @param refining its refinement, where shown; else null
     * @param repairs the repairs made of each kind
     * @param scene the scene it is shown in
     * @param view the view: its animation, caption and geometry
     */
    public record Outcome(Request request, HalfedgeMesh mesh, RefineJob.Outcome refining, Map<Defect, Integer> repairs, Scene scene,
            Scenes.View view) {
        /** The same view in another scene (the window's second view of it). */
        public Scenes.View viewIn(Scene another) {
            return Scenes.view(another, request.model().getFileName().toString(), mesh, refinement(), request.show(), request.colors());
        }

        /** The refinement shown, or null. */
        public HamiltonianRefinement.Result refinement() {
            return refining == null ? null : refining.refinement();
        }

        /**
         * What the view is, for a report: the model; the counts and angles {@code ifold refine}
         * prints and the view's edges by kind where refined, else its faces and triangles; the
         * repairs.
         */
        public Map<String, Object> figures() {
            Map<String, Object> figures = new LinkedHashMap<>();
            figures.put("model", request.model().toString());
            if (refining != null) {
                figures.putAll(refining.figures());
                int[] edges = PathView.edgeKindCounts(view.geometry().mesh());
                figures.put("treeEdges", edges[0]);
                figures.put("steinerEdges", edges[1]);
                figures.put("originalEdges", edges[2]);
            } else {
                figures.put("faces", mesh.faceCount());
                figures.put("triangles", view.geometry().mesh().triangleCount());
            }
            figures.put("repairs", Reports.repairs(repairs));
            return figures;
        }
    }

    /**
     * Reads, builds, refines where asked, and makes the view.
     *
     * @throws ModelFiles.LoadFailure where the file cannot be read or built, or its repairs leave no faces
     * @throws java.util.concurrent.CancellationException once the watcher says stop
     */
    public static Outcome run(Request request, JobWatcher watcher) throws ModelFiles.LoadFailure {
        Path model = request.model();
        boolean refined = request.show() != Scenes.Show.MODEL;
        ModelFiles.Loaded loaded = ModelFiles.loadSurface(model, new MeshBuilder.Options(request.strict(), refined), "show", watcher);
        HalfedgeMesh mesh = loaded.built().mesh();
        if (mesh.faceCount() == 0) {
            throw new ModelFiles.LoadFailure(model + ": no faces to show", false);
        }
        watcher.stopIfAsked();
        RefineJob.Outcome refining = null;
        if (refined) {
            watcher.stage("refining " + mesh.faceCount() + " triangles");
            refining = RefineJob.run(mesh, false);
            watcher.stopIfAsked();
        }
        Scene scene = new Scene();
        Scenes.View view = Scenes.view(scene, model.getFileName().toString(), mesh, refining == null ? null : refining.refinement(),
                request.show(), request.colors());
        return new Outcome(request, mesh, refining, loaded.repairs(), scene, view);
    }
}
