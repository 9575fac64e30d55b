"""The peer of `ifold info` in bench/run: libigl reads a mesh and builds its triangle adjacency."""
import sys
import igl

vertices, faces = igl.read_triangle_mesh(sys.argv[1])
adjacency, _ = igl.triangle_triangle_adjacency(faces)
print(f"{vertices.shape[0]} vertices, {faces.shape[0]} faces, {adjacency.shape[0]} adjacency rows")
