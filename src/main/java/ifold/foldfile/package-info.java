/**
 * The FOLD file format (edemaine/fold, spec 1.2), the format every origami tool reads: folded
 * sheets written as their crease pattern (the key frame, in paper coordinates) and their folded
 * state (a 3D frame with the stacking order of overlapping faces). Mountain and valley are
 * measured against the paper's own top side, as crease patterns mean them.
 */
package ifold.foldfile;
