/**
 * Paper and folds with thickness, after the seed (sections 3.3 and 3.4). A {@link ifold.fold.Paper}
 * is a set of convex polygons, each vertex with its 3D position and its paper coordinates (u, v):
 * where it lies on the unfolded sheet. A fold slices every layer with a plane, splits faces
 * exactly on it, turns the region on one side about an axis offset so that layers end one
 * paper thickness apart, and bridges the fold with a cap of two facets. Paper faces only ever
 * move rigidly, so their 3D edge lengths equal their paper edge lengths: the isometry tests
 * check exactly that. Pure Java: no GL.
 */
package ifold.fold;
