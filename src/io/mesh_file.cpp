#include "grpvss/io/mesh_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <system_error>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <Eigen/Core>

#include "assimp_import.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/text_file.hpp"

namespace grpvss::io {
namespace {

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;  // u = 2^-53

double gamma(int n) { return n * kUnitRoundoff / (1 - n * kUnitRoundoff); }

enum class MeshFormat { kStl, kCollada, kObj };

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

MeshFormat format_of(const std::string& path) {
  const std::string extension = lower_case(std::filesystem::path(path).extension().string());
  if (extension == ".stl") return MeshFormat::kStl;
  if (extension == ".dae") return MeshFormat::kCollada;
  if (extension == ".obj") return MeshFormat::kObj;
  throw InputError(path, 0, "a mesh file ending in .stl, .dae or .obj",
                   extension.empty() ? "no extension" : "extension " + extension);
}

void check_file(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) {
    throw InputError(path, 0, "an existing mesh file", "no such file");
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw InputError(path, 0, "a mesh file", "not a regular file");
  }
  const auto size = std::filesystem::file_size(path, error);
  if (error || size > kMaxInputFileBytes) {
    throw InputError(path, 0, "a mesh file of at most " + std::to_string(kMaxInputFileBytes) +
                                  " bytes",
                     error ? error.message() : std::to_string(size) + " bytes");
  }
}

void check_scale(const std::string& path, const Eigen::Vector3d& scale) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(scale[i]) || scale[i] == 0.0) {
      char text[64];
      std::snprintf(text, sizeof text, "%.17g", scale[i]);
      throw InputError(path, 0, "a finite, nonzero mesh scale", std::string("scale component ") + text);
    }
  }
}

// A node's transform composed from the root, with an entrywise bound E >= |M^ - M| on its
// rounding (proof: proofs/urdf-frames.md#mesh-vertices). `identity` marks an exact identity,
// which is never multiplied (so STL and OBJ vertices stay exact).
struct NodeTransform {
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d E = Eigen::Matrix4d::Zero();
  bool identity = true;
};

Eigen::Matrix4d node_matrix(const std::string& path, const aiNode& node) {
  const aiMatrix4x4& m = node.mTransformation;
  Eigen::Matrix4d N;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      N(r, c) = static_cast<double>(m[static_cast<unsigned>(r)][static_cast<unsigned>(c)]);
      if (!std::isfinite(N(r, c))) {
        throw InputError(path, 0, "finite node transforms",
                         "a non-finite entry in node '" + std::string(node.mName.C_Str()) + "'");
      }
    }
  }
  if (N(3, 0) != 0.0 || N(3, 1) != 0.0 || N(3, 2) != 0.0 || N(3, 3) != 1.0) {
    throw InputError(path, 0, "affine node transforms (last row 0 0 0 1)",
                     "node '" + std::string(node.mName.C_Str()) + "'");
  }
  return N;
}

// parent * N, with E_child = (E_parent + gamma_4 |M_parent|) |N| (Higham's inner-product bound).
NodeTransform compose(const NodeTransform& parent, const Eigen::Matrix4d& N) {
  if (N == Eigen::Matrix4d::Identity()) return parent;
  if (parent.identity) return {N, Eigen::Matrix4d::Zero(), false};
  NodeTransform child;
  child.M = parent.M * N;
  child.E = (parent.E + gamma(4) * parent.M.cwiseAbs()) * N.cwiseAbs();
  child.identity = false;
  return child;
}

// The Y-up -> Z-up turn (x, y, z) -> (x, -z, y): exact (entries 0, +-1).
Eigen::Matrix4d y_up_to_z_up() {
  Eigen::Matrix4d P = Eigen::Matrix4d::Zero();
  P(0, 0) = 1.0;
  P(1, 2) = -1.0;
  P(2, 1) = 1.0;
  P(3, 3) = 1.0;
  return P;
}

// One vertex: float32 coordinates -> node transform -> scale, with its error bound.
struct PlacedVertex {
  Eigen::Vector3d p;
  double error;
};

PlacedVertex place_vertex(const aiVector3D& v, const NodeTransform& transform,
                          const MeshReadOptions& options) {
  const Eigen::Vector4d v_file(static_cast<double>(v.x), static_cast<double>(v.y),
                               static_cast<double>(v.z), 1.0);
  Eigen::Vector3d p = v_file.head<3>();
  Eigen::Vector3d bound = Eigen::Vector3d::Zero();
  if (!transform.identity) {
    const Eigen::Vector4d p4 = transform.M * v_file;
    const Eigen::Vector4d b4 =
        transform.E * v_file.cwiseAbs() + gamma(4) * (transform.M.cwiseAbs() * v_file.cwiseAbs());
    p = p4.head<3>();
    bound = b4.head<3>();
  }
  for (int i = 0; i < 3; ++i) {
    const double s = options.scale[i];
    if (s == 1.0 && options.scale_is_exact) continue;
    const double scaled = p[i] * s;
    // exact scale: |s| b + gamma_1 |fl(p s)|; rounded scale: |s| ((1 + gamma_1) b + gamma_2 |p|).
    // proof: proofs/urdf-frames.md#mesh-vertices
    bound[i] = options.scale_is_exact
                   ? std::abs(s) * bound[i] + gamma(1) * std::abs(scaled)
                   : std::abs(s) * ((1 + gamma(1)) * bound[i] + gamma(2) * std::abs(p[i]));
    p[i] = scaled;
  }
  return {p, bound.norm()};
}

ImportedScene import_scene(const std::string& path, const MeshReadOptions& options) {
  // Triangulate splits polygons without moving vertices; no step that transforms positions.
  ImportedScene scene = import_with_assimp(path, aiProcess_Triangulate, options.apply_collada_up_axis);
  if (scene->mRootNode == nullptr) {
    throw InputError(path, 0, "a mesh with a scene node", "none");
  }
  return scene;
}

// Collects the triangles of every node, vertices deduplicated by exact position.
class MeshCollector {
 public:
  MeshCollector(const std::string& path, const aiScene& scene, const MeshReadOptions& options)
      : path_(path), scene_(scene), options_(options) {}

  void visit(const aiNode& node, const NodeTransform& parent, int depth) {
    if (depth > 256) throw InputError(path_, 0, "a node hierarchy at most 256 deep", "deeper");
    const NodeTransform transform = compose(parent, node_matrix(path_, node));
    int part = -1;
    for (unsigned k = 0; k < node.mNumMeshes; ++k) {
      if (node.mMeshes[k] >= scene_.mNumMeshes) {
        throw InputError(path_, 0, "node meshes that exist", "a dangling mesh index");
      }
      const aiMesh& mesh = *scene_.mMeshes[node.mMeshes[k]];
      if (add_triangles(mesh, transform) && part < 0) part = start_part(node);
      for (std::size_t t = mesh_first_triangle_; t < result_.mesh.triangles.size(); ++t) {
        result_.mesh.triangle_part.push_back(part);
      }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) visit(*node.mChildren[c], transform, depth + 1);
  }

  MeshFile finish(MeshFormat format) {
    if (result_.mesh.triangles.empty()) {
      throw InputError(path_, 0, "a mesh with at least one triangle", "none");
    }
    const bool named = format != MeshFormat::kStl &&
                       !(format == MeshFormat::kObj && result_.mesh.part_names.size() == 1 &&
                         result_.mesh.part_names[0] == "defaultobject");
    if (!named) {
      result_.mesh.part_names.clear();
      result_.mesh.triangle_part.clear();
    }
    result_.mesh.source = path_;
    // The bound was evaluated in double on non-negative terms (relative error far below 1/2):
    // doubling covers it. proof: proofs/urdf-frames.md#evaluating-bounds
    result_.vertex_error *= 2;
    return std::move(result_);
  }

 private:
  int start_part(const aiNode& node) {
    result_.mesh.part_names.emplace_back(node.mName.C_Str());
    return static_cast<int>(result_.mesh.part_names.size()) - 1;
  }

  bool add_triangles(const aiMesh& mesh, const NodeTransform& transform) {
    mesh_first_triangle_ = result_.mesh.triangles.size();
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines are not surfaces
      std::array<int, 3> triangle{};
      for (int k = 0; k < 3; ++k) {
        const unsigned index = face.mIndices[k];
        if (index >= mesh.mNumVertices) {
          throw InputError(path_, 0, "face indices within the mesh", "index " + std::to_string(index));
        }
        triangle[static_cast<std::size_t>(k)] = vertex_index(mesh.mVertices[index], transform);
      }
      if (result_.mesh.triangles.size() >= kMaxMeshElements) {
        throw InputError(path_, 0, "at most " + std::to_string(kMaxMeshElements) + " triangles",
                         "more");
      }
      result_.mesh.triangles.push_back(triangle);
    }
    return result_.mesh.triangles.size() > mesh_first_triangle_;
  }

  int vertex_index(const aiVector3D& v, const NodeTransform& transform) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      throw InputError(path_, 0, "finite vertex coordinates", "NaN or infinity");
    }
    const PlacedVertex placed = place_vertex(v, transform, options_);
    if (!placed.p.allFinite()) {
      throw InputError(path_, 0, "vertices that stay finite when scaled", "an overflow");
    }
    const std::array<double, 3> key{placed.p.x(), placed.p.y(), placed.p.z()};
    const auto [it, inserted] =
        index_.emplace(key, static_cast<int>(result_.mesh.vertices.size()));
    if (inserted) {
      result_.mesh.vertices.push_back(placed.p);
      result_.vertex_error = std::max(result_.vertex_error, placed.error);
    }
    return it->second;
  }

  const std::string& path_;
  const aiScene& scene_;
  const MeshReadOptions& options_;
  MeshFile result_;
  std::map<std::array<double, 3>, int> index_;
  std::size_t mesh_first_triangle_ = 0;
};

}  // namespace

MeshFile read_mesh_file(const std::string& path, const MeshReadOptions& options) {
  const MeshFormat format = format_of(path);
  check_file(path);
  check_scale(path, options.scale);
  const ImportedScene scene = import_scene(path, options);
  NodeTransform root;
  if (format == MeshFormat::kCollada && options.apply_collada_up_axis) {
    // assimp turned the file's up axis onto +y; one exact turn more puts it on +z.
    root.M = y_up_to_z_up();
    root.identity = false;
  }
  MeshCollector collector(path, *scene, options);
  collector.visit(*scene->mRootNode, root, 0);
  return collector.finish(format);
}

}  // namespace grpvss::io
