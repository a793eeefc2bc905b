// CONT files: a write/read round trip keeps every field, 1-based numbering on disk, and a
// damaged file is refused with the name of the file and of the array.
#include "contact/contact_elements.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "scratch_folder.hpp"
#include "square_mesh.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <type_traits>

namespace sig {
namespace {

// One folder for the file's tests, removed when the test program ends.
std::filesystem::path temp_path(const std::string& name) {
  static const testing::ScratchFolder dir;
  return dir / name;
}

void expect_same(const ContactElements& a, const ContactElements& b) {
  EXPECT_EQ(a.num_nodes, b.num_nodes);
  EXPECT_EQ(a.ref, b.ref);
  EXPECT_EQ(a.thickness, b.thickness);
  EXPECT_EQ(a.node, b.node);
  EXPECT_EQ(a.lagrange_node, b.lagrange_node);
  EXPECT_EQ(a.normal, b.normal);
  EXPECT_EQ(a.tangent, b.tangent);
  EXPECT_EQ(a.gap, b.gap);
  EXPECT_EQ(a.weight, b.weight);
  EXPECT_EQ(a.law, b.law);
  EXPECT_EQ(a.obstacle.kind, b.obstacle.kind);
  EXPECT_EQ(a.obstacle.point, b.obstacle.point);
  EXPECT_EQ(a.obstacle.normal, b.obstacle.normal);
  EXPECT_EQ(a.obstacle.radius, b.obstacle.radius);
}

TEST(ContIo, RoundTripPlaneAndDisc) {
  const Mesh mesh = test::square_mesh(4, 1.0, 0.125, test::scrambled(4));
  const HalfPlane plane({0, 0}, {0.1, 1});
  const Disc disc({0.5, -3}, 3);
  // Every law and parameter survives, the truncation "none" included.
  ContactLaw unilateral;
  unilateral.normal = NormalLaw::compliance_unilateral;
  unilateral.cn = 10;
  unilateral.depth = 0.01;
  unilateral.friction = FrictionLaw::coulomb;
  unilateral.mu = 0.3;
  ContactLaw truncated;
  truncated.normal = NormalLaw::compliance;
  truncated.cn = 7;
  truncated.c3 = 1e8;
  truncated.friction = FrictionLaw::tresca;
  truncated.threshold = 2;
  ContactLaw nonmonotone = unilateral;
  nonmonotone.friction = FrictionLaw::nonmonotone;
  nonmonotone.a = 2;
  nonmonotone.b = 0.02;
  nonmonotone.alpha = 100;
  nonmonotone.mu = 1.5;
  nonmonotone.bound = FrictionBound::compliance;
  nonmonotone.of = SlipMeasure::slip_rate;
  ContactLaw damped;
  damped.normal = NormalLaw::damped_unilateral;
  damped.cn = 10;
  damped.depth = 0.05;
  for (const ContactLaw& law : {unilateral, truncated, nonmonotone, damped, ContactLaw{}})
    for (const Obstacle* obstacle :
         {static_cast<const Obstacle*>(&plane), static_cast<const Obstacle*>(&disc)}) {
      const ContactElements written = build_contact_elements(mesh, 3, *obstacle, law, 0.5);
      const auto path = temp_path("case_" + obstacle->kind() + ".cont");
      write_cont(path, written, "round trip");
      expect_same(read_cont(path, mesh), written);

      // On disk the numbering is 1-based and Lagrange nodes follow the mesh nodes.
      const Ds ds = read_ds(path, "CONT");
      EXPECT_EQ(ds.header.creator, "sig-contact");
      const auto node = ds.ints("node");
      const auto lagrange = ds.ints("lagrange_node");
      for (int i = 0; i < written.size(); ++i) {
        EXPECT_EQ(node[i], written.node[i] + 1);
        EXPECT_EQ(lagrange[i], mesh.num_nodes() + i + 1);
      }
      EXPECT_EQ(ds.shape("normal"), (std::vector<std::int64_t>{written.size(), 2}));
      EXPECT_EQ(ds.integer("num_nodes"), mesh.num_nodes());
      EXPECT_EQ(ds.text("obstacle_kind"), obstacle->kind());
    }
}

// A CONT file rewritten with one array changed.
template <class Value>
std::filesystem::path damaged(const std::string& array, const std::vector<Value>& values) {
  const Mesh mesh = test::square_mesh(2);
  const auto path = temp_path("damaged_" + array + ".cont");
  write_cont(path, build_contact_elements(mesh, 3, HalfPlane({0, 0}, {0, 1})));
  Ds ds = read_ds(path, "CONT");
  if constexpr (std::is_same_v<Value, double>)
    ds.put(array, values, {}, Finite::not_required); // a damaged file, as an editor may make it
  else
    ds.put(array, values);
  write_ds(path, ds);
  return path;
}

void expect_error_naming(const std::filesystem::path& path, const std::string& what) {
  try {
    read_cont(path, test::square_mesh(2)); // the mesh of damaged()
    ADD_FAILURE() << "no error for " << what;
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }
}

TEST(ContIo, InconsistentFilesAreRefused) {
  // 3 elements on a 9-node mesh: nodes 1, 2, 3; Lagrange nodes 10, 11, 12.
  using Ints = std::vector<std::int64_t>;
  expect_error_naming(damaged("lagrange_node", Ints{10, 12, 11}), "lagrange_node");
  expect_error_naming(damaged("node", Ints{1, 2, 10}), "node");
  expect_error_naming(damaged("law", Ints{1, 7, 1}), "law");
  expect_error_naming(damaged("friction_law", Ints{0, 4, 0}), "friction_law");
  expect_error_naming(damaged("friction_bound", Ints{0, 2, 0}), "friction_bound");
  expect_error_naming(damaged("friction_of", Ints{0, 0, -1}), "friction_of");
  expect_error_naming(damaged("friction_alpha", std::vector<double>{0, -1, 0}),
                      "array friction_alpha, element 2");
  expect_error_naming(damaged("friction_b", std::vector<double>{0, 1, 0}),
                      "array friction_b, element 2"); // b = 1 > a = 0
  // A compliance law without its slope: the ranges of the card reader hold for the file too.
  expect_error_naming(damaged("law", Ints{1, 2, 1}), "array cn, element 2");
  // An unused parameter out of range is refused all the same (a signorini element's cn, c3).
  expect_error_naming(damaged("cn", std::vector<double>{0, -1, 0}), "array cn, element 2");
  expect_error_naming(damaged("c3", std::vector<double>{0, 0, -5}), "array c3, element 3");
  expect_error_naming(damaged("node", std::vector<std::int64_t>{1, 2}), "length");
  expect_error_naming(damaged("mu", std::vector<double>{0, -1, 0}), "array mu, element 2");
  expect_error_naming(damaged("depth", std::vector<double>{0, 0, NAN}),
                      "array 'depth': value 3 of 3 is NaN");
  expect_error_naming(damaged("tangent", std::vector<double>{1, 0, -1, 0, 1, 0}),
                      "array tangent, element 2");
  // The geometry in its ranges (core/ranges.hpp), the CRC rewritten: a gap or a weight of 1e300
  // (the unit square's weights are at most its diagonal, sqrt(2)), of another mesh's size.
  expect_error_naming(damaged("gap", std::vector<double>{0, 1e300, 0}),
                      "array 'gap', row 2: 1e+300");
  expect_error_naming(damaged("weight", std::vector<double>{0.25, 0.5, 1e300}),
                      "array 'weight', row 3: 1e+300 is not in (0, 1.41421]");
  expect_error_naming(damaged("weight", std::vector<double>{0.25, 0.5, 2}),
                      "array 'weight', row 3");
  expect_error_naming(damaged("weight", std::vector<double>{0.25, 0, 0.25}),
                      "array 'weight', row 2");
  expect_error_naming(damaged("thickness", std::vector<double>{0}), "array 'thickness', row 1");
}

TEST(ContIo, OtherKindIsRefused) {
  const auto path = temp_path("not_cont.ds");
  Ds ds("MILI", "not contact", "test");
  ds.put_int("num_nodes", 1);
  write_ds(path, ds);
  EXPECT_THROW(read_cont(path, test::square_mesh(2)), Error);
}

} // namespace
} // namespace sig
