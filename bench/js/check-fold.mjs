// Reads FOLD files as other tools do and says what each finds wrong: the FOLD library of
// Erik Demaine (edemaine/fold: per-edge and per-face keys as long as the edges and faces, the
// faces it derives from the edges, its warnings) and Rabbit Ear's graph.validate.
// Usage: node check-fold.mjs FILE.fold ...; prints a line a file, exits 1 if any has a problem.
import fs from "fs";
import { createRequire } from "module";
const require = createRequire(import.meta.url);
const FOLD = require("fold");
const ear = (await import("rabbit-ear")).default;
let bad = 0;
for (const file of process.argv.slice(2)) {
  const fold = JSON.parse(fs.readFileSync(file, "utf8"));
  const problems = [];
  const edges = fold.edges_vertices.length;
  const faces = fold.faces_vertices ? fold.faces_vertices.length : 0;
  for (const [key, value] of Object.entries(fold)) {
    if (key.startsWith("edges_") && Array.isArray(value) && value.length !== edges) problems.push(`${key} has ${value.length} for ${edges} edges`);
    if (key.startsWith("faces_") && Array.isArray(value) && value.length !== faces) problems.push(`${key} has ${value.length} for ${faces} faces`);
  }
  const said = [];
  const log = console.log;
  const warn = console.warn;
  console.log = console.warn = (...words) => said.push(words.join(" "));
  try {
    const copy = JSON.parse(JSON.stringify(fold));
    delete copy.faces_vertices;
    delete copy.faces_edges;
    FOLD.convert.edges_vertices_to_vertices_vertices_sorted(copy);
    FOLD.convert.vertices_vertices_to_faces_vertices(copy);
    // The faces it derives: the file's, and the outside of the paper.
    if (copy.faces_vertices.length !== faces + 1 && copy.faces_vertices.length !== faces) {
      problems.push(`the FOLD library derives ${copy.faces_vertices.length} faces from its edges, the file has ${faces}`);
    }
  } catch (e) {
    problems.push(`the FOLD library failed: ${e.message}`);
  }
  console.log = log;
  console.warn = warn;
  problems.push(...said.map((s) => `the FOLD library says: ${s}`));
  const valid = ear.graph.validate(fold);
  if (valid.summary !== "valid") problems.push(`Rabbit Ear: ${JSON.stringify(valid)}`);
  console.log(`${file}: ${problems.length ? problems.slice(0, 3).join("; ") : "accepted by the FOLD library and Rabbit Ear"}`);
  bad += problems.length ? 1 : 0;
}
process.exit(bad ? 1 : 0);
