/**
 * An independent check of folded paper for collisions: {@link ifold.check.PaperCollisions} reads
 * the OBJ that a wrap or a fold script exports and finds every pair of its triangles that cross
 * (deeper than a thousandth of the paper's thickness), layers that overlap in one plane, and
 * paper that crosses or enters the model. It shares no code with the fold engine and imports
 * nothing but the JDK, so that a fault of the engine cannot hide itself here.
 */
package ifold.check;
