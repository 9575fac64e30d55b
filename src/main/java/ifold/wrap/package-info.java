/**
 * Wrapping a whole polyhedron with one strip per component, along the Hamiltonian path of its
 * refinement: the planner ({@link ifold.wrap.Wrap}), the strips placed in space with their caps
 * ({@link ifold.wrap.PaperInSpace}), their measures ({@link ifold.wrap.WrapAnalysis}) and OBJ
 * export ({@link ifold.wrap.WrapExport}). Pure Java: no GL.
 */
package ifold.wrap;
