/**
 * The Hamiltonian refinement of Arkin, Held, Mitchell and Skiena: any triangulated surface is
 * refined so that a path through the dual graph visits every triangle once, consecutive
 * triangles sharing an edge. That path is what the zig-zag strip follows from triangle to
 * triangle. {@link ifold.refine.CycleCoverPath} finds such a path through a closed mesh's own
 * triangles, cutting only the few it splices at.
 */
package ifold.refine;
