/**
 * The index-based halfedge mesh, its builder from polygon soup and its validator. Pure Java: no
 * GL, no AWT.
 *
 * <h2>Vocabulary</h2>
 * Every element is an {@code int} handle; {@code -1} means none.
 * <pre>
 *                     toVertex(h)
 *                         o
 *            next(h)    / ^ | \    prev(twin(h))
 *                     /   | |   \
 *          face(h)  /    h| |twin  \  face(twin(h))
 *                   \     | |(h)   /
 *                     \   | |    /
 *            prev(h)    \ | v  /     next(twin(h))
 *                         o
 *               fromVertex(h) = toVertex(twin(h))
 * </pre>
 * {@code h} runs up the left of the shared edge, with its face on its left; {@code twin(h)}
 * runs down the right, with the other face.
 * <ul>
 *   <li>{@code twin(h) = h ^ 1} and {@code edge(h) = h >>> 1}: the two halfedges of an edge are
 *       stored side by side, so neither needs an array.</li>
 *   <li>{@code next(h)} and {@code prev(h)} walk the loop of {@code face(h)} counter-clockwise
 *       seen from outside (from the side the normal points to).</li>
 *   <li>A boundary halfedge has {@code face(h) == -1}; boundary halfedges form loops of their own
 *       through {@code next}/{@code prev}, running clockwise around the hole.</li>
 *   <li>{@code halfedge(v)} is an outgoing halfedge of {@code v}; for a vertex on the boundary
 *       it is the boundary halfedge leaving it, so {@code isBoundary(v)} costs one look-up.</li>
 *   <li>Around a vertex, {@code twin(prev(h))} is the next outgoing halfedge counter-clockwise
 *       and {@code next(twin(h))} the next one clockwise.</li>
 * </ul>
 */
package ifold.mesh;
