/**
 * The fold engine for wrapping: a strip's sheet of paper as it is laid onto the triangles of a
 * surface. Paper faces rest on host triangles, each with a rigid pose from paper coordinates
 * into its host's 2D frame ({@link ifold.sheet.Isometry2}, {@link ifold.sheet.HostFrame}) and a
 * level in the host's stack; the strip not yet laid is one piece with one pose, so a fold of it
 * costs O(1), and a tuck cuts and moves only the faces on its triangle
 * ({@link ifold.sheet.Sheet}). Pure Java: no GL.
 */
package ifold.sheet;
