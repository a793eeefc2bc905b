// summary.json and contact.csv: stable keys and header, the contact table joined from case.cont
// and case.b with the sign conventions of the contact module, and the NaN guard of sig-post.
#include "post/summary.hpp"

#include "core/error.hpp"
#include "post/contact_table.hpp"
#include "post/result_checks.hpp"
#include "post_test_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace sig {
namespace {

// "\"key\":" as the one-line JSON writes it.
std::string key_of(const char* key) {
  std::string quoted = "\"";
  quoted += key;
  quoted += "\":";
  return quoted;
}

Ds solved(const std::string& method) {
  Ds b("B", "solution", "test");
  // Node 5 (index 4) went down by the whole gap and touches; nodes 1 and 2 went down less.
  std::vector<double> u(10, 0.0);
  u[0] = 0.01, u[1] = -0.05;  // node 1
  u[2] = -0.01, u[3] = -0.02; // node 2
  u[8] = 0.0, u[9] = -0.1;    // node 5
  b.put("u", u);
  b.put_text("method", method);
  b.put_text("linear", "cholmod");
  b.put_int("converged", 1);
  b.put_int("iterations", 4);
  b.put_int("dofs", method == "alm" ? 13 : 10); // 5 nodes, 3 Lagrange nodes for alm
  b.put("multiplier", std::vector<double>{0.0, 3.0, 0.0});
  b.put("tangential_multiplier", std::vector<double>{0.0, -1.5, 0.0});
  b.put("status", std::vector<std::int64_t>{0, 1, 0});
  b.put("normal_status", std::vector<std::int64_t>{0, 2, 0});
  b.put("friction_status", std::vector<std::int64_t>{0, 3, 0});
  b.put("history_active", std::vector<std::int64_t>{3, 1, 1, 1});
  b.put("history_residual", std::vector<double>{1.0, 0.5, 0.125, 0.0625});
  b.put_scalar("time_factorize", 0.25);
  b.put_scalar("time_solve", 0.5);
  return b;
}

TEST(ContactTable, JoinsElementsWithTheirFinalState) {
  const Mesh mesh = test::small_mesh();
  const auto rows = contact_rows(mesh, test::bottom_contact(), solved("alm"));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].node, 1);
  EXPECT_EQ(rows[1].node, 5);
  EXPECT_EQ(rows[2].node, 2);
  EXPECT_EQ(rows[1].x1, 1.0);
  EXPECT_EQ(rows[1].x2, 0.0);
  EXPECT_EQ(rows[0].u1, 0.01);
  EXPECT_EQ(rows[0].u2, -0.05);
  // u_n = -n . u: moving down by 0.05 against the normal (0, 1) closes the gap 0.1 to 0.05.
  EXPECT_NEAR(rows[0].gap, 0.05, 1e-15);
  EXPECT_NEAR(rows[1].gap, 0.0, 1e-15);
  EXPECT_NEAR(rows[2].gap, 0.08, 1e-15);
  EXPECT_EQ(rows[1].multiplier, 3.0);
  EXPECT_EQ(rows[1].pressure, 3.0); // weight 1
  EXPECT_TRUE(rows[1].contact);
  EXPECT_FALSE(rows[0].contact);
  EXPECT_EQ(rows[1].normal_status, NormalStatus::unilateral);
  EXPECT_EQ(rows[1].friction_status, FrictionStatus::slip_backward);
  EXPECT_EQ(rows[1].tangential_multiplier, -1.5);
  EXPECT_EQ(rows[1].tangential_pressure, -1.5);
  // The slip is the tangential displacement t . u, t = (1, 0).
  EXPECT_EQ(rows[0].slip, 0.01);
  EXPECT_EQ(rows[2].slip, -0.01);
}

TEST(ContactTable, DisagreeingSizesAndBadNodesAreErrors) {
  const Mesh mesh = test::small_mesh();
  Ds b = solved("pdas");
  b.put("normal_status", std::vector<std::int64_t>{0, 2});
  EXPECT_THROW(contact_rows(mesh, test::bottom_contact(), b), Error);
  b = solved("pdas");
  b.put("friction_status", std::vector<std::int64_t>{0, 9, 0}); // no such status
  EXPECT_THROW(contact_rows(mesh, test::bottom_contact(), b), Error);
  Ds cont = test::bottom_contact();
  cont.put("node", std::vector<std::int64_t>{1, 6, 2});
  EXPECT_THROW(contact_rows(mesh, cont, solved("pdas")), Error);
}

TEST(ContactTable, CsvHeaderAndRows) {
  const auto rows = contact_rows(test::small_mesh(), test::bottom_contact(), solved("alm"));
  const auto csv = contact_csv(rows, true);
  const std::string header = "node,x1,x2,u1,u2,gap,multiplier,pressure,status,normal_status,"
                             "friction_status,tangential_multiplier,tangential_pressure,slip,"
                             "converged\n";
  ASSERT_EQ(csv.substr(0, header.size()), header);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
  EXPECT_NE(csv.find("\n5,1,0,0,-0.10000000000000001,0,3,3,contact,CU,S-,-1.5,-1.5,0,1\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\n1,0,0,0.01"), std::string::npos);
  EXPECT_NE(csv.find(",free,free,-,0,0,"), std::string::npos);
  // A solve that did not converge says so on every row.
  const auto nv = contact_csv(rows, false);
  EXPECT_EQ(std::count(nv.begin(), nv.end(), '\n'), 4);
  std::size_t rows_nv = 0;
  for (std::size_t at = nv.find("\n"); at + 1 < nv.size(); at = nv.find("\n", at + 1))
    rows_nv += nv.compare(nv.find("\n", at + 1) - 2, 2, ",0") == 0;
  EXPECT_EQ(rows_nv, 3u) << nv;
}

TEST(ContactTable, SamplesAreCentred) {
  const auto rows = contact_rows(test::small_mesh(), test::bottom_contact(), solved("alm"));
  const auto samples = pressure_samples(rows, 1.0);
  EXPECT_EQ(samples[0].x, -1.0);
  EXPECT_EQ(samples[1].x, 0.0);
  EXPECT_EQ(samples[2].x, 1.0);
  EXPECT_EQ(samples[1].weight, 1.0);
}

TEST(Summary, AFailedSolveNamesItsReasonAndDrift) {
  const Mesh mesh = test::small_mesh();
  Ds b = solved("alm");
  b.put_int("converged", 0);
  b.put_text("failure", "drift: a rigid motion of the body is held by no contact");
  b.put_text("failure_reason", "drift");
  b.put_scalar("drift", 8.7e6);
  const auto rows = contact_rows(mesh, test::bottom_contact(), b);
  const std::string json = build_summary("Nv", mesh, b, rows, gather_times({&b})).dump(-1);
  EXPECT_NE(json.find("\"converged\":false,\"failure\":\"drift\",\"failure_detail\":\"drift: a "
                      "rigid motion"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"drift\":8700000"), std::string::npos) << json;
}

TEST(Summary, KeysInStableOrderWithValuesFromTheSolution) {
  const Mesh mesh = test::small_mesh();
  const Ds b = solved("alm");
  const auto rows = contact_rows(mesh, test::bottom_contact(), b);
  const std::string json = build_summary("Hertz N=8", mesh, b, rows, gather_times({&b})).dump(-1);
  const char* keys[] = {
      "title",     "method",      "converged",        "failure",           "iterations",
      "dofs",      "multipliers", "contact_elements", "contact_nodes",     "nodes",
      "triangles", "backend",     "residual_history", "increment_history", "active_history",
      "times"};
  EXPECT_NE(json.find("\"normal_status_counts\":{\"free\":2,\"CN\":0,\"CU\":1}"), std::string::npos)
      << json;
  EXPECT_NE(json.find("\"friction_status_counts\":{\"-\":2,\"S=\":0,\"S+\":0,\"S-\":1}"),
            std::string::npos)
      << json;
  std::size_t last = 0;
  for (const char* key : keys) {
    const auto at = json.find(key_of(key));
    ASSERT_NE(at, std::string::npos) << key;
    EXPECT_GT(at, last) << key;
    last = at;
  }
  EXPECT_NE(json.find("\"method\":\"alm\""), std::string::npos);
  EXPECT_NE(json.find("\"converged\":true"), std::string::npos);
  EXPECT_NE(json.find("\"iterations\":4"), std::string::npos);
  EXPECT_NE(json.find("\"multipliers\":3"), std::string::npos);
  EXPECT_NE(json.find("\"contact_nodes\":1"), std::string::npos);
  EXPECT_NE(json.find("\"nodes\":5,\"triangles\":3"), std::string::npos);
  EXPECT_NE(json.find("\"backend\":\"cholmod\""), std::string::npos);
  EXPECT_NE(json.find("\"residual_history\":[1,0.5,0.125,0.0625]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"increment_history\":[]"), std::string::npos);
  EXPECT_NE(json.find("\"active_history\":[3,1,1,1]"), std::string::npos);
  EXPECT_NE(json.find("\"times\":{\"factorize\":0.25,\"solve\":0.5}"), std::string::npos);
}

TEST(Summary, MultipliersAreUnknownsOfAlmOnly) {
  const Mesh mesh = test::small_mesh();
  Ds b = solved("pdas");
  b.put_int("converged", 0);
  const auto rows = contact_rows(mesh, test::bottom_contact(), b);
  const std::string json = build_summary("t", mesh, b, rows, {}).dump(-1);
  EXPECT_NE(json.find("\"multipliers\":0"), std::string::npos);
  EXPECT_NE(json.find("\"contact_elements\":3"), std::string::npos);
  EXPECT_NE(json.find("\"converged\":false"), std::string::npos);
  EXPECT_NE(json.find("\"times\":{}"), std::string::npos);
}

TEST(Summary, TimesOfLaterStagesReplaceEarlierOnes) {
  Ds tae("TAE", "t", "test");
  tae.put_scalar("time_assemble", 1.0);
  tae.put_scalar("time_solve", 9.0);
  tae.put_scalar("timeless", 3.0);
  Ds b("B", "t", "test");
  b.put_scalar("time_solve", 2.0);
  const auto times = gather_times({&tae, nullptr, &b});
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[0], (std::pair<std::string, double>{"assemble", 1.0}));
  EXPECT_EQ(times[1], (std::pair<std::string, double>{"solve", 2.0}));
}

TEST(Summary, HertzJsonHasTheReferenceBesideOurs) {
  const HertzData d;
  PressureError e;
  e.p_max = 14.4;
  const std::string json = hertz_json(d, e).dump(-1);
  for (const char* key :
       {"b", "p0", "p_max", "p_max_rel_error", "half_width", "half_width_error", "l2_rel_error"}) {
    EXPECT_NE(json.find(key_of(key)), std::string::npos) << key;
  }
  EXPECT_NE(json.find("\"p_max\":14.4"), std::string::npos);
}

// The active set per iteration is [iterations x contact nodes] of 0 / 1 and the start's
// fraction in [0, 1]: a file with another shape, code or fraction is refused.
TEST(SolutionChecks, HistoryWallHasOneRowOfFlagsPerIteration) {
  const Mesh mesh = test::small_mesh();
  Ds b = solved("pdas");
  const std::vector<std::int64_t> wall{1, 1, 1, 0, 1, 0, 0, 1, 0, 0, 1, 0};
  b.put("history_wall", wall, {4, 3});
  EXPECT_NO_THROW(verify_solution_ds(b, mesh));
  b.put("history_wall", std::vector<std::int64_t>(9, 0), {3, 3});
  EXPECT_THROW(
      try { verify_solution_ds(b, mesh); } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'history_wall' is not 4 iterations x 3"),
                  std::string::npos)
            << e.what();
        throw;
      },
      Error);
  b.put("history_wall", wall, {4, 3});
  b.put_scalar("start_fraction", 1.5);
  EXPECT_THROW(verify_solution_ds(b, mesh), Error);
  b.put_scalar("start_fraction", 0.5);
  EXPECT_NO_THROW(verify_solution_ds(b, mesh));
  std::vector<std::int64_t> bad = wall;
  bad[4] = 2;
  b.put("history_wall", bad, {4, 3});
  EXPECT_THROW(verify_solution_ds(b, mesh), Error);
}

} // namespace
} // namespace sig
