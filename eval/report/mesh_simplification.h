#pragma once
// A triangle mesh cut to a triangle budget for the report page, by vertex clustering (Rossignac
// and Borrel, 1993): the vertices in each cell of a uniform grid merge into one, at their mean
// position with their mean colour; a triangle left with fewer than three distinct vertices, or
// with the same three as an earlier one, goes. Cruder than quadric decimation (edges and thin
// parts blur at the cell's size), but a page's preview needs no more, and it is linear in the
// mesh and deterministic. Hand-written: the stack's one decimator, PCL's, goes through VTK, which
// the report does not link.
#include <cstddef>

#include "fusion/ply_cloud.h"

namespace slamkit::eval {

// `mesh` itself when it has at most `budget` triangles. Else the clustered mesh, on a grid
// coarsened step by step from the surface's area until at most `budget` triangles are left; its
// vertices are numbered in the order the triangles first use them, without normals. The same
// mesh and budget give the same mesh.
PlyCloud simplify_mesh(const PlyCloud& mesh, size_t budget);

}  // namespace slamkit::eval
