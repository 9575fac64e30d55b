package ifold.fold;

import ifold.io.AtomicFile;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/**
 * Writes a folded paper as OBJ: each vertex's 3D position as {@code v} and its paper coordinates
 * as {@code vt} (same index, in paper units), paper faces in group {@code paper} and cap facets in
 * group {@code cap}, so that anyone can check that the paper did not stretch. Written under a
 * temporary name and renamed: a failed export leaves no half-written file.
 */
public final class PaperExport {
    private PaperExport() {
    }

    public static void writeObj(Paper paper, Path file) throws IOException {
        AtomicFile.write(file, stream -> {
            Writer out = new BufferedWriter(new OutputStreamWriter(stream, StandardCharsets.UTF_8));
            int caps = 0;
            for (int f = 0; f < paper.faceCount(); f++) {
                caps += paper.isCap(f) ? 1 : 0;
            }
            out.write("# iFold folded paper: " + paper.vertexCount() + " vertices, " + paper.faceCount() + " faces ("
                    + caps + " cap facets), thickness " + paper.thickness() + "\n");
            out.write("# vt holds each vertex's paper coordinates (u, v): where it lies on the unfolded sheet\n");
            for (int v = 0; v < paper.vertexCount(); v++) {
                out.write("v " + paper.x(v) + " " + paper.y(v) + " " + paper.z(v) + "\n");
            }
            for (int v = 0; v < paper.vertexCount(); v++) {
                out.write("vt " + paper.u(v) + " " + paper.v(v) + "\n");
            }
            for (boolean capGroup : new boolean[] {false, true}) {
                out.write(capGroup ? "g cap\n" : "g paper\n");
                for (int f = 0; f < paper.faceCount(); f++) {
                    if (paper.isCap(f) != capGroup) {
                        continue;
                    }
                    StringBuilder line = new StringBuilder("f");
                    for (int v : paper.face(f)) {
                        line.append(' ').append(v + 1).append('/').append(v + 1);
                    }
                    out.write(line.append('\n').toString());
                }
            }
            out.flush();
        }, true);
    }
}
