/**
 * Independent checks of folded paper: {@link ifold.check.PaperCollisions} reads the OBJ that a
 * wrap or a fold script exports and finds every pair of its triangles that cross (deeper than a
 * thousandth of the paper's thickness), layers that overlap in one plane, and paper that crosses
 * or enters the model; {@link ifold.check.LayerOrder} reads a FOLD file's folded state and tests
 * its order of layers against flat folding's rules; {@link ifold.check.WrapTruths} reads a wrap's
 * OBJ and the model's triangles and checks the five truths of a wrap. They share no code with the
 * fold engine and import nothing but the JDK (and jackson-core to read FOLD), so that a fault of
 * the engine cannot hide itself here.
 */
package ifold.check;
