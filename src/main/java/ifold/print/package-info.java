/**
 * Paper to print and fold: the crease pattern of a strip or sheet at real size, cut into
 * pieces that fit a page, with glue tabs and marks where they join, valley and mountain folds
 * in their line styles (Yoshizawa–Randlett), each crease numbered in folding order, a legend and
 * a 5 cm scale bar; drawn once onto a {@link ifold.print.Canvas}, which writes SVG or PDF.
 */
package ifold.print;
