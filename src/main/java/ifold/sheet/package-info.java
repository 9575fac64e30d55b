/**
 * The fold engine: a sheet of paper as it is folded onto hosts, the triangles of a surface (a
 * wrap) or planes in space (a fold script). Paper faces rest on hosts, each with a rigid pose
 * from paper coordinates into its host's 2D frame ({@link ifold.sheet.Isometry2},
 * {@link ifold.sheet.HostFrame}) and a level in the host's stack; a strip's part not yet laid is
 * one piece with one pose, so a fold of it costs O(1), and an edit of laid paper (a tuck, a fold
 * of a script) cuts and moves only the faces it takes ({@link ifold.sheet.Sheet}). Pure Java: no
 * GL.
 */
package ifold.sheet;
