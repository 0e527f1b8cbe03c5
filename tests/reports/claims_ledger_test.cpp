// The ledger of claims (reports/document/claims.hpp) against the verifier that shares no code with
// it (tools/verify_claims.py): a report's claims hold on its own data, and a value planted in a
// data file makes exactly the claims that rest on it fail, each named.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_helpers.hpp"
#include "reports/document/report.hpp"
#include "small_report.hpp"

namespace steplab {
namespace {

using Json = nlohmann::ordered_json;

Json read_doc(const std::string& path) { return Json::parse(slurp(path)); }
void write_doc(const std::string& path, const Json& j) { std::ofstream(path) << j.dump(1) << "\n"; }

// A small report of the sheet's question in the full report's words (answers, the family table),
// without the stability section: its claims cite data/stability/stability.json all the same.
struct LedgerReport {
  TempDir dir;
  std::string out = dir.path("report");
  LedgerReport() {
    ReportConfig c = small_config();
    c.sections = {"answers", "families"};
    EXPECT_EQ(write_report(c, out, true), 0);
  }
  std::string file(const std::string& name) const { return out + "/data/" + name; }
};

TEST(ClaimsLedger, TheSheetsQuestionIsClaimedAndHoldsOnItsData) {
  const LedgerReport r;
  const Json claims = read_doc(r.file("claims.json"));
  EXPECT_EQ(claims["schema"], "steplab.claims/1");
  std::set<std::string> ids;
  for (const Json& c : claims["claims"]) ids.insert(c["id"].get<std::string>());
  for (const char* id : {"answers.unstable_at_large_dt", "answers.unstable_undamped", "answers.order_correlation", "answers.trend.bdf",
                         "families.trend.bdf.damping_0", "families.trend.bdf.damping_0.1"})
    EXPECT_TRUE(ids.count(id)) << id;
  EXPECT_TRUE(std::filesystem::exists(r.file("stability/stability.json")));  // cited, though its section is left out
  const Result v = verify_claims(r.out);
  EXPECT_EQ(v.status, 0) << v.out << v.err;
}

// Explicit Euler made stable at the sheet's large step in the data: the answer that it is not
// fails; BDF3's dt* at damping 0 made unbounded: its family no longer falls there.
TEST(ClaimsLedger, APlantedValueFailsTheClaimsThatRestOnIt) {
  const LedgerReport r;
  const std::string path = r.file("stability/stability.json");
  Json doc = read_doc(path);
  const ReportConfig c = small_config();
  int planted = 0;
  for (Json& row : doc["sweep"])
    if (row["method"] == "explicit_euler" && row["dt"] == c.large_dt && row["damping"] == c.damping()) {
      ASSERT_EQ(row["stable"], false);
      row["stable"] = true;
      ++planted;
    }
  for (Json& row : doc["thresholds"])
    if (row["method"] == "bdf3" && row["damping"] == 0.0) {
      ASSERT_NE(row["dt_measured"], "unbounded");
      row["dt_measured"] = "unbounded";
      ++planted;
    }
  ASSERT_EQ(planted, 2);
  write_doc(path, doc);
  const Result v = verify_claims(r.out);
  EXPECT_EQ(v.status, 1);
  for (const char* id : {"answers.unstable_at_large_dt:", "families.trend.bdf.damping_0:"})
    EXPECT_NE(v.out.find(id), std::string::npos) << id << " not named:\n" << v.out;
  EXPECT_EQ(v.out.find("answers.unstable_undamped:"), std::string::npos) << v.out;  // rests on other rows
  EXPECT_EQ(v.out.find("families.trend.bdf.damping_0.1:"), std::string::npos) << v.out;
}

// The sections' findings beyond the sheet's question: the energy classes, the stiff orders, the
// long run's classes, the collision orders and the output between steps are claims that hold;
// a value planted in a document fails the claims that read it (its recorded value no longer the
// file's), and only those.
TEST(ClaimsLedger, TheSectionsFindingsAreClaimedAndAPlantedValueFailsThem) {
  TempDir dir;
  const std::string out = dir.path("report");
  ReportConfig c = small_config();
  c.sections = {"energy", "stiff_order", "long_time", "collision", "dense_output", "stability"};
  ASSERT_EQ(write_report(c, out, true), 0);
  const Result before = verify_claims(out);
  ASSERT_EQ(before.status, 0) << before.out << before.err;
  const Json claims = read_doc(out + "/data/claims.json");
  std::set<std::string> ids;
  for (const Json& cl : claims["claims"]) ids.insert(cl["id"].get<std::string>());
  for (const char* id : {"energy.bounded", "stiff_order.falls", "long_time.orbit.bounded", "long_time.orbit.lost",
                         "collision.bounce_order.kept", "dense_output.kept", "stability.thresholds_agree"})
    EXPECT_TRUE(ids.count(id)) << id;
  EXPECT_GE(claims["theory"].size(), 3u);

  // velocity Verlet's energy made to grow in its second half: no longer bounded, now growing or decaying
  Json energy = read_doc(out + "/data/energy/energy.json");
  for (Json& row : energy["rows"])
    if (row["method"] == "velocity_verlet") row["second_half"] = 10 * row["first_half"].get<double>() + 1e-3;
  write_doc(out + "/data/energy/energy.json", energy);
  // Radau IIA's stiff limit made order 5: it no longer falls
  Json stiff = read_doc(out + "/data/stiff_order/stiff_order.json");
  for (Json& row : stiff["methods"])
    if (row["method"] == "radau_iia5") row["stiff"]["order"] = 5.0, row["stiff"]["order_bound"] = {4.99, 5.01};
  write_doc(out + "/data/stiff_order/stiff_order.json", stiff);
  const Result v = verify_claims(out);
  EXPECT_EQ(v.status, 1);
  for (const char* id : {"energy.bounded:", "stiff_order.falls:"})
    EXPECT_NE(v.out.find(id), std::string::npos) << id << " not named:\n" << v.out;
  // and the class it now falls in, growing or decaying by its E/E0 at the end, names it too
  EXPECT_TRUE(v.out.find("energy.grows:") != std::string::npos || v.out.find("energy.decays:") != std::string::npos) << v.out;
  // the claims that read no planted value: blowing up reads no half, the others other documents
  for (const char* id : {"energy.blows_up:", "long_time.orbit.bounded:", "dense_output.kept:", "collision.bounce_order.kept:"})
    EXPECT_EQ(v.out.find(id), std::string::npos) << id << " named:\n" << v.out;
}

}  // namespace
}  // namespace steplab
