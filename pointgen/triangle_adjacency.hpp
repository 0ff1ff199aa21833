#pragma once
#include "pointgen/triangle_mesh.hpp"

#include <cstdint>
#include <vector>

namespace pointgen {

// The mesh's triangles with their neighbours, for GL_TRIANGLES_ADJACENCY: six indices a triangle,
// (a, across ab, b, across bc, c, across ca), where "across ab" is the vertex opposite the edge in
// the one other triangle that shares it. Edges are matched by position, so seams that repeat a
// vertex for its normals or colours still join. An edge with no such neighbour (the mesh's border,
// or an edge three or more triangles share) gets the triangle's own third vertex: the triangle,
// turned over, stands for the neighbour, and so faces the light the other way.
std::vector<std::uint32_t> adjacency_indices(const TriangleMesh& mesh);

}  // namespace pointgen
