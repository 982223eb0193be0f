#include "grpvss/io/mesh_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <gtest/gtest.h>

#include "grpvss/common/input_error.hpp"
#include "support/text_files.hpp"

namespace grpvss::io {
namespace {

using Float50 = boost::multiprecision::cpp_bin_float_50;

const std::string kRobots = std::string(GRPVSS_SOURCE_DIR) + "/../shared/robots/";

// Binary STL read by hand: 80-byte header, uint32 count, 50-byte facets (normal, 3 vertices,
// attribute), little endian float32.
std::vector<std::array<Eigen::Vector3d, 3>> binary_stl_triangles(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  std::vector<std::array<Eigen::Vector3d, 3>> triangles(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* facet = bytes.data() + 84 + 50 * t;
    for (int v = 0; v < 3; ++v) {
      float xyz[3];
      std::memcpy(xyz, facet + 12 + 12 * v, 12);
      triangles[t][static_cast<std::size_t>(v)] = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
    }
  }
  return triangles;
}

TEST(MeshFile, BinaryStlVerticesAreTheFilesFloat32ValuesExactly) {
  for (const std::string name : {"ur5e/ur_description/meshes/ur5e/collision/upperarm.stl",
                                 "franka_panda/franka_description/meshes/collision/hand.stl"}) {
    const std::string path = kRobots + name;
    const MeshFile file = read_mesh_file(path);
    const auto expected = binary_stl_triangles(path);
    ASSERT_EQ(file.mesh.triangles.size(), expected.size()) << name;
    for (std::size_t t = 0; t < expected.size(); ++t) {
      for (std::size_t v = 0; v < 3; ++v) {
        const int index = file.mesh.triangles[t][v];
        ASSERT_EQ(file.mesh.vertices[static_cast<std::size_t>(index)], expected[t][v]) << name << " triangle " << t;
      }
    }
    EXPECT_EQ(file.vertex_error, 0.0);
    EXPECT_TRUE(file.mesh.part_names.empty());
    EXPECT_EQ(file.mesh.source, path);
  }
  EXPECT_EQ(read_mesh_file(kRobots + "ur5e/ur_description/meshes/ur5e/collision/upperarm.stl").mesh.vertices.size(), 998u);
}

class MeshFileOnDisk : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = test::make_temporary_directory("mesh-file"); }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = directory_ + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::string directory_;
};

const std::string kAsciiTetrahedron =
    "solid t\n"
    "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0.5 1.25 0\nvertex 2 0 0\nendloop\nendfacet\n"
    "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 2 0 0\nvertex 0 0 -3\nendloop\nendfacet\n"
    "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 -3\nvertex 0.5 1.25 0\nendloop\nendfacet\n"
    "facet normal 1 1 1\nouter loop\nvertex 2 0 0\nvertex 0.5 1.25 0\nvertex 0 0 -3\nendloop\nendfacet\n"
    "endsolid t\n";

TEST_F(MeshFileOnDisk, AsciiStlIsDeduplicatedByExactPosition) {
  const MeshFile file = read_mesh_file(write("t.STL", kAsciiTetrahedron));
  ASSERT_EQ(file.mesh.vertices.size(), 4u);
  EXPECT_EQ(file.mesh.triangles.size(), 4u);
  EXPECT_EQ(file.mesh.vertices[0], Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(file.mesh.vertices[1], Eigen::Vector3d(0.5, 1.25, 0));
  EXPECT_EQ(file.mesh.vertices[2], Eigen::Vector3d(2, 0, 0));
  EXPECT_EQ(file.mesh.vertices[3], Eigen::Vector3d(0, 0, -3));
  EXPECT_EQ(file.mesh.triangles[3], (std::array<int, 3>{2, 1, 3}));
  EXPECT_EQ(file.vertex_error, 0.0);
}

// The scale is a decimal's nearest double: each vertex is within vertex_error of
// (float32 value) * (decimal), checked in 50 digits. proof: proofs/urdf-frames.md#mesh-vertices
TEST_F(MeshFileOnDisk, ScaleIsAppliedWithinItsBoundOfTheDecimalScale) {
  MeshReadOptions options;
  options.scale = Eigen::Vector3d(0.001, 3, 1.1);
  options.scale_is_exact = false;
  const MeshFile file = read_mesh_file(write("t.stl", kAsciiTetrahedron), options);
  EXPECT_EQ(file.mesh.vertices[1], Eigen::Vector3d(0.5 * 0.001, 1.25 * 3, 0));
  EXPECT_GT(file.vertex_error, 0.0);
  const std::array<Float50, 3> decimal{Float50("0.001"), Float50("3"), Float50("1.1")};
  const std::vector<Eigen::Vector3d> raw{{0, 0, 0}, {0.5, 1.25, 0}, {2, 0, 0}, {0, 0, -3}};
  for (std::size_t k = 0; k < raw.size(); ++k) {
    Float50 squared = 0;
    for (int i = 0; i < 3; ++i) {
      const Float50 d = Float50(file.mesh.vertices[k][i]) - Float50(raw[k][i]) * decimal[static_cast<std::size_t>(i)];
      squared += d * d;
    }
    EXPECT_LE(static_cast<double>(sqrt(squared)), file.vertex_error);
  }
  EXPECT_LT(file.vertex_error, 1e-14);
}

std::string dae(const std::string& unit, const std::string& up, const std::string& outer,
                const std::string& inner, const std::string& positions) {
  return "<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" "
         "version=\"1.4.1\">\n<asset><unit name=\"u\" meter=\"" + unit + "\"/><up_axis>" + up +
         "</up_axis></asset>\n<library_geometries><geometry id=\"g\"><mesh>\n"
         "<source id=\"p\"><float_array id=\"pa\" count=\"12\">" + positions + "</float_array>"
         "<technique_common><accessor source=\"#pa\" count=\"4\" stride=\"3\"><param name=\"X\" "
         "type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/>"
         "</accessor></technique_common></source>\n<vertices id=\"v\"><input semantic=\"POSITION\" "
         "source=\"#p\"/></vertices>\n<triangles count=\"4\"><input semantic=\"VERTEX\" source=\"#v\" "
         "offset=\"0\"/><p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles>\n</mesh></geometry></library_geometries>\n"
         "<library_visual_scenes><visual_scene id=\"s\"><node id=\"outer\" name=\"outer\">" + outer +
         "<node id=\"part\" name=\"part\">" + inner + "<instance_geometry url=\"#g\"/></node></node>"
         "</visual_scene></library_visual_scenes>\n<scene><instance_visual_scene url=\"#s\"/></scene>\n</COLLADA>\n";
}

TEST_F(MeshFileOnDisk, ColladaUnitAndNodeTransformsAreApplied) {
  // millimetres; the part node is moved by (1, 2, 3) mm.
  const MeshFile file = read_mesh_file(
      write("mm.dae", dae("0.001", "Z_UP", "", "<translate>1 2 3</translate>", "0 0 0 10 0 0 0 20 0 0 0 30")));
  ASSERT_EQ(file.mesh.vertices.size(), 4u);
  const std::vector<Eigen::Vector3d> expected{{0.001, 0.002, 0.003}, {0.001, 0.022, 0.003},
                                              {0.011, 0.002, 0.003}, {0.001, 0.002, 0.033}};
  for (std::size_t k = 0; k < 4; ++k) {
    // The unit is assimp's float32 0.001: within a relative 2^-24 of the decimal.
    EXPECT_LT((file.mesh.vertices[k] - expected[k]).norm(), 1e-7 * expected[k].norm()) << k;
  }
  EXPECT_EQ(file.mesh.part_names, (std::vector<std::string>{"part"}));
  EXPECT_EQ(file.mesh.triangle_part, (std::vector<int>{0, 0, 0, 0}));
}

TEST_F(MeshFileOnDisk, ColladaUpAxisIsKeptByDefaultAndTurnedOntoZOnRequest) {
  const std::string positions = "0 0 0 1 0 0 0 1 0 0 0 1";
  for (const std::string up : {"X_UP", "Y_UP", "Z_UP"}) {
    const std::string path = write("up.dae", dae("1", up, "", "", positions));
    const MeshFile kept = read_mesh_file(path);
    EXPECT_EQ(kept.mesh.vertices[1], Eigen::Vector3d(0, 1, 0)) << up;  // as in the file
    MeshReadOptions options;
    options.apply_collada_up_axis = true;
    const MeshFile turned = read_mesh_file(path, options);
    // The file's up axis ends on +z; vertex k+1 is the file's unit vector e_k.
    const int up_index = up == "X_UP" ? 0 : up == "Y_UP" ? 1 : 2;
    EXPECT_EQ(turned.mesh.vertices[static_cast<std::size_t>(up_index == 0 ? 2 : up_index == 1 ? 1 : 3)],
              Eigen::Vector3d(0, 0, 1)) << up;
    for (const Eigen::Vector3d& v : turned.mesh.vertices) EXPECT_LE(v.norm(), 1.0);
  }
}

// Node matrices, unit and vertices exactly representable in float32, so the exact model is
// known to the test: |vertex - unit * M_outer * M_part * v * scale| <= vertex_error (50 digits).
TEST_F(MeshFileOnDisk, ColladaTransformArithmeticIsWithinItsBound) {
  const std::string outer = "<matrix>0.5 0 0.25 1.5 0 2 0 -0.75 0.125 0 1 3 0 0 0 1</matrix>";
  const std::string inner = "<translate>0.375 -2.5 1.25</translate>";
  MeshReadOptions options;
  options.scale = Eigen::Vector3d(0.1, 1, 7);
  options.scale_is_exact = false;
  const MeshFile file = read_mesh_file(
      write("m.dae", dae("0.5", "Z_UP", outer, inner, "0 0 0 3.5 0 0 0 -1.75 0 0.3125 0 6")), options);
  using M = Eigen::Matrix<Float50, 4, 4>;
  M outer_m, inner_m = M::Identity(), unit = M::Identity();
  outer_m << 0.5, 0, 0.25, 1.5, 0, 2, 0, -0.75, 0.125, 0, 1, 3, 0, 0, 0, 1;
  inner_m(0, 3) = 0.375;
  inner_m(1, 3) = -2.5;
  inner_m(2, 3) = 1.25;
  for (int i = 0; i < 3; ++i) unit(i, i) = 0.5;
  const M total = unit * outer_m * inner_m;
  const std::array<Float50, 3> scale{Float50("0.1"), Float50("1"), Float50("7")};
  const std::vector<Eigen::Vector3d> raw{{0, 0, 0}, {0, -1.75, 0}, {3.5, 0, 0}, {0.3125, 0, 6}};
  ASSERT_EQ(file.mesh.vertices.size(), 4u);
  EXPECT_GT(file.vertex_error, 0.0);
  EXPECT_LT(file.vertex_error, 1e-12);
  for (std::size_t k = 0; k < raw.size(); ++k) {
    Float50 squared = 0;
    for (int r = 0; r < 3; ++r) {
      Float50 exact = total(r, 3);
      for (int c = 0; c < 3; ++c) exact += total(r, c) * Float50(raw[k][c]);
      const Float50 d = Float50(file.mesh.vertices[k][r]) - exact * scale[static_cast<std::size_t>(r)];
      squared += d * d;
    }
    EXPECT_LE(static_cast<double>(sqrt(squared)), file.vertex_error) << k;
  }
}

TEST_F(MeshFileOnDisk, ObjObjectsAndGroupsBecomeParts) {
  const std::string two =
      "o first\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
      "o second\nv 2 0 0\nv 3 0 0\nv 2 1 0\nv 2 0 1\ng sub\nf 5 7 6\nf 5 6 8\nf 5 8 7 6\n";
  const MeshFile parts = read_mesh_file(write("two.obj", two));
  EXPECT_EQ(parts.mesh.part_names, (std::vector<std::string>{"first", "sub"}));
  EXPECT_EQ(parts.mesh.triangle_part, (std::vector<int>{0, 0, 0, 0, 1, 1, 1, 1}));  // the quad split in two
  EXPECT_EQ(parts.mesh.vertices.size(), 8u);
  const MeshFile plain = read_mesh_file(write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n"));
  EXPECT_TRUE(plain.mesh.part_names.empty());
  EXPECT_TRUE(plain.mesh.triangle_part.empty());
  EXPECT_EQ(plain.mesh.triangles.size(), 2u);
}

void expect_mesh_error(const std::string& path, const MeshReadOptions& options, const std::string& message) {
  try {
    (void)read_mesh_file(path, options);
    ADD_FAILURE() << "no InputError; expected " << message;
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.line(), 0);
    EXPECT_EQ(std::string(error.what()), path + ":0: " + message);
  }
}

TEST_F(MeshFileOnDisk, BadFilesAreInputErrorsNamingTheFile) {
  const MeshReadOptions options;
  expect_mesh_error(directory_ + "/missing.stl", options, "expected an existing mesh file, found no such file");
  expect_mesh_error(write("mesh.ply", "ply\n"), options, "expected a mesh file ending in .stl, .dae or .obj, found extension .ply");
  std::filesystem::create_directory(directory_ + "/folder.stl");
  expect_mesh_error(directory_ + "/folder.stl", options, "expected a mesh file, found not a regular file");
  expect_mesh_error(write("empty.obj", "# nothing\n"), options,
                    "expected a mesh assimp can read, found OBJ-file is too small.");
  expect_mesh_error(write("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n"), options,
                    "expected a mesh with at least one triangle, found none");
  std::string nan_stl(84 + 50, '\0');
  const std::uint32_t one = 1;
  std::memcpy(&nan_stl[80], &one, 4);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan_stl[84 + 12], &nan, 4);
  expect_mesh_error(write("nan.stl", nan_stl), options, "expected finite vertex coordinates, found NaN or infinity");
  MeshReadOptions zero;
  zero.scale = Eigen::Vector3d(1, 0, 1);
  expect_mesh_error(write("t.stl", kAsciiTetrahedron), zero, "expected a finite, nonzero mesh scale, found scale component 0");
}

}  // namespace
}  // namespace grpvss::io
