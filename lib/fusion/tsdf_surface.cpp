#include "fusion/tsdf_surface.h"

// PCL's marching cubes tables (Lorensen and Cline's cases as Paul Bourke tabulated them): the
// edges each of the 256 sign patterns cuts and the triangles over them.
#include <pcl/surface/marching_cubes.h>

#include <algorithm>
#include <cmath>

namespace slamkit {
namespace {

constexpr int kSide = kTsdfBlockSide;
// A crossing needs both values short of the truncation (Open3D's extraction uses 0.98 too).
constexpr int kNearTruncation = int(0.98f * 32767);

// A block and the 26 around it: voxels addressed by coordinates local to the centre block,
// each within -8..15.
class Neighbourhood {
 public:
  Neighbourhood(const TsdfVolume& volume, const TsdfBlock& centre) {
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const size_t s = slot(dx + 1, dy + 1, dz + 1);
          ordinals_[s] = volume.ordinal(centre.index + Eigen::Array3i(dx, dy, dz));
          blocks_[s] = ordinals_[s] < 0 ? nullptr : volume.blocks()[size_t(ordinals_[s])].get();
        }
  }

  const TsdfVoxel* voxel(int x, int y, int z) const {
    const TsdfBlock* block = blocks_[slot(part(x), part(y), part(z))];
    return block ? &block->voxels[size_t(local_index(x, y, z))] : nullptr;
  }
  long ordinal(int x, int y, int z) const { return ordinals_[slot(part(x), part(y), part(z))]; }
  // The voxel's index within its own block.
  static int local_index(int x, int y, int z) {
    return TsdfBlock::voxel_at(x - kSide * (part(x) - 1), y - kSide * (part(y) - 1),
                               z - kSide * (part(z) - 1));
  }

 private:
  static int part(int c) { return c < 0 ? 0 : c < kSide ? 1 : 2; }
  static size_t slot(int px, int py, int pz) { return size_t(px + 3 * (py + 3 * pz)); }

  std::array<const TsdfBlock*, 27> blocks_{};
  std::array<long, 27> ordinals_{};
};

// A block's crossings: vertices in voxel order, each named by (voxel index * 3 + axis).
struct BlockVertices {
  std::vector<uint16_t> edges;  // ascending
  std::vector<Eigen::Vector3f> points, normals;
  std::vector<Rgb8> colours;
};

class SurfaceExtractor {
 public:
  SurfaceExtractor(const TsdfVolume& volume, float min_weight)
      : volume_(volume),
        min_weight_(std::max<uint32_t>(1, uint32_t(std::ceil(min_weight * kTsdfWeightUnits)))) {}

  BlockVertices vertices(const TsdfBlock& block) const {
    const Neighbourhood around(volume_, block);
    BlockVertices out;
    const Eigen::Vector3f corner = (block.index * kSide).cast<float>().matrix();
    for (int z = 0; z < kSide; ++z)
      for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
          const TsdfVoxel* v = around.voxel(x, y, z);
          if (!usable(v)) continue;
          const Eigen::Array3i at(x, y, z);
          for (int axis = 0; axis < 3; ++axis) {
            Eigen::Array3i next = at;
            ++next[axis];
            const TsdfVoxel* n = around.voxel(next.x(), next.y(), next.z());
            if (!usable(n) || (v->tsdf < 0) == (n->tsdf < 0)) continue;
            const float tv = tsdf_value(*v), tn = tsdf_value(*n);
            const float share = tv / (tv - tn);
            Eigen::Vector3f position = corner + at.cast<float>().matrix() +
                                       Eigen::Vector3f::Constant(0.5f);
            position[axis] += share;
            Eigen::Vector3f normal =
                (1 - share) * gradient(around, at) + share * gradient(around, next);
            if (normal.squaredNorm() == 0) normal[axis] = tn > tv ? 1.0f : -1.0f;
            out.edges.push_back(uint16_t(TsdfBlock::voxel_at(x, y, z) * 3 + axis));
            out.points.push_back(position * volume_.voxel_size());
            out.normals.push_back(normal.normalized());
            Rgb8 colour;
            for (size_t c = 0; c < 3; ++c)
              colour[c] = uint8_t(std::lround((1 - share) * v->rgb[c] + share * n->rgb[c]));
            out.colours.push_back(colour);
          }
        }
    return out;
  }

  // The marching cubes triangles of the cubes whose first corner is in `block`, as indices into
  // the whole surface: offsets[b] is block b's first vertex.
  std::vector<std::array<uint32_t, 3>> triangles(const TsdfBlock& block,
                                                 const std::vector<BlockVertices>& vertices,
                                                 const std::vector<uint32_t>& offsets) const {
    // PCL's corner order (MarchingCubes::getNeighborList1D) and the corners of each edge.
    static constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1},
                                          {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};
    static constexpr int kEdge[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                         {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    const Neighbourhood around(volume_, block);
    std::vector<std::array<uint32_t, 3>> out;
    for (int z = 0; z < kSide; ++z)
      for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
          int cube = 0;
          bool seen = true;
          for (int c = 0; c < 8 && seen; ++c) {
            const TsdfVoxel* v = around.voxel(x + kCorner[c][0], y + kCorner[c][1], z + kCorner[c][2]);
            seen = v && v->weight >= min_weight_;
            if (seen && v->tsdf < 0) cube |= 1 << c;
          }
          if (!seen || pcl::edgeTable[cube] == 0) continue;
          std::array<long, 12> vertex;
          bool complete = true;
          for (int e = 0; e < 12 && complete; ++e) {
            if (!(pcl::edgeTable[cube] & (1u << e))) continue;
            const int* a = kCorner[kEdge[e][0]];
            const int* b = kCorner[kEdge[e][1]];
            const int axis = a[0] != b[0] ? 0 : a[1] != b[1] ? 1 : 2;
            const int vx = x + std::min(a[0], b[0]), vy = y + std::min(a[1], b[1]),
                      vz = z + std::min(a[2], b[2]);
            vertex[size_t(e)] = find_vertex(around, vx, vy, vz, axis, vertices, offsets);
            complete = vertex[size_t(e)] >= 0;
          }
          if (!complete) continue;
          for (const int* t = pcl::triTable[cube]; *t != -1; t += 3)
            out.push_back({uint32_t(vertex[size_t(t[0])]), uint32_t(vertex[size_t(t[1])]),
                           uint32_t(vertex[size_t(t[2])])});
        }
    return out;
  }

 private:
  bool usable(const TsdfVoxel* v) const {
    return v && v->weight >= min_weight_ && std::abs(int(v->tsdf)) < kNearTruncation;
  }

  // Central differences where both sides are seen, one-sided where one is.
  Eigen::Vector3f gradient(const Neighbourhood& around, const Eigen::Array3i& at) const {
    const float here = tsdf_value(*around.voxel(at.x(), at.y(), at.z()));
    Eigen::Vector3f g = Eigen::Vector3f::Zero();
    for (int axis = 0; axis < 3; ++axis) {
      Eigen::Array3i plus = at, minus = at;
      ++plus[axis];
      --minus[axis];
      const TsdfVoxel* p = around.voxel(plus.x(), plus.y(), plus.z());
      const TsdfVoxel* m = around.voxel(minus.x(), minus.y(), minus.z());
      const bool has_p = p && p->weight > 0, has_m = m && m->weight > 0;
      if (has_p && has_m)
        g[axis] = 0.5f * (tsdf_value(*p) - tsdf_value(*m));
      else if (has_p)
        g[axis] = tsdf_value(*p) - here;
      else if (has_m)
        g[axis] = here - tsdf_value(*m);
    }
    return g;
  }

  static long find_vertex(const Neighbourhood& around, int x, int y, int z, int axis,
                          const std::vector<BlockVertices>& vertices,
                          const std::vector<uint32_t>& offsets) {
    const long block = around.ordinal(x, y, z);
    if (block < 0) return -1;
    const std::vector<uint16_t>& edges = vertices[size_t(block)].edges;
    const uint16_t edge = uint16_t(Neighbourhood::local_index(x, y, z) * 3 + axis);
    const auto it = std::lower_bound(edges.begin(), edges.end(), edge);
    if (it == edges.end() || *it != edge) return -1;
    return long(offsets[size_t(block)]) + long(it - edges.begin());
  }

  const TsdfVolume& volume_;
  uint32_t min_weight_;  // in kTsdfWeightUnits
};

}  // namespace

PlyCloud extract_surface(const TsdfVolume& volume, float min_weight, bool triangles) {
  const SurfaceExtractor extractor(volume, min_weight);
  const auto& blocks = volume.blocks();
  std::vector<BlockVertices> per_block(blocks.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (long b = 0; b < long(blocks.size()); ++b)
    per_block[size_t(b)] = extractor.vertices(*blocks[size_t(b)]);

  std::vector<uint32_t> offsets(blocks.size() + 1, 0);
  for (size_t b = 0; b < blocks.size(); ++b)
    offsets[b + 1] = offsets[b] + uint32_t(per_block[b].points.size());
  PlyCloud cloud;
  if (triangles) {
    std::vector<std::vector<std::array<uint32_t, 3>>> faces(blocks.size());
#pragma omp parallel for schedule(dynamic, 16)
    for (long b = 0; b < long(blocks.size()); ++b)
      faces[size_t(b)] = extractor.triangles(*blocks[size_t(b)], per_block, offsets);
    for (const auto& block_faces : faces)
      cloud.triangles.insert(cloud.triangles.end(), block_faces.begin(), block_faces.end());
  }
  cloud.points.reserve(offsets.back());
  cloud.normals.reserve(offsets.back());
  cloud.colours.reserve(offsets.back());
  for (BlockVertices& block : per_block) {
    cloud.points.insert(cloud.points.end(), block.points.begin(), block.points.end());
    cloud.normals.insert(cloud.normals.end(), block.normals.begin(), block.normals.end());
    cloud.colours.insert(cloud.colours.end(), block.colours.begin(), block.colours.end());
    block = {};
  }
  return cloud;
}

PlyCloud referenced_vertices(PlyCloud mesh) {
  constexpr uint32_t kUnused = ~uint32_t(0);
  std::vector<uint32_t> renumbered(mesh.points.size(), kUnused);
  PlyCloud out;
  for (std::array<uint32_t, 3>& triangle : mesh.triangles)
    for (uint32_t& index : triangle) {
      if (renumbered[index] == kUnused) {
        renumbered[index] = uint32_t(out.points.size());
        out.points.push_back(mesh.points[index]);
        out.colours.push_back(mesh.colours[index]);
        if (!mesh.normals.empty()) out.normals.push_back(mesh.normals[index]);
      }
      index = renumbered[index];
    }
  out.triangles = std::move(mesh.triangles);
  return out;
}

}  // namespace slamkit
