/**
 * The Hamiltonian refinement of Arkin, Held, Mitchell and Skiena: any triangulated surface is
 * refined so that a path through the dual graph visits every triangle once, consecutive
 * triangles sharing an edge. That path is what the zig-zag strip follows from triangle to
 * triangle.
 */
package ifold.refine;
