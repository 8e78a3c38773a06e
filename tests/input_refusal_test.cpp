// Every input but scenes (tolerance files, sweep specs, engines files) through the one reader:
// the cases that once crashed or were taken silently, each refused naming the file and field.
// And the CSV every table is written and read with.
// ctest-label: unit
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "compare/io/atomic_file.h"
#include "compare/io/csv.h"
#include "compare/studies/sweep.h"
#include "compare/studies/tolerances.h"
#include "source_root.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;
using test::kRoot;

class InputFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("springcheck_inputs_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  // A sweep spec over the seed circle with `fields` spliced in.
  std::string spec(const std::string& fields) {
    return file("spec.json",
                R"({"scenes": [")" + kRoot + R"(/scenes/seed/circle.json"], )" + fields + "}");
  }
  fs::path dir_;
  EngineRegistry registry_;
};

void expectRefused(const std::expected<SweepSpec, std::string>& r, const std::string& source,
                   const std::string& field) {
  ASSERT_FALSE(r) << "accepted";
  EXPECT_EQ(r.error().rfind(source + ": ", 0), 0u) << r.error();
  EXPECT_NE(r.error().find(field), std::string::npos) << r.error();
}

TEST_F(InputFiles, SweepSpecFieldsOfTheWrongTypeAreRefusedNamingTheField) {
  const std::string rest = R"("dt": [0.1], "reference": "closed_form")";
  for (auto [fields, field] : std::vector<std::pair<std::string, std::string>>{
           {R"("name": 5, )" + rest, "name: expected a string"},
           {R"("name": null, )" + rest, "name: expected a string"},
           {R"("dt": [0.1], "reference": {"integrator": 4})", "reference.integrator"},
           {R"("dt": [0.1], "reference": {"integrator": "rk4", "refnie": 4})",
            "reference.refnie: unknown field"},
           {R"("dt": [1e400], "reference": "closed_form")", "dt[0]: expected a number within"},
           {R"("dt": [0.5], "duration": 0.08, "reference": "closed_form")",
            "dt[0]: a step no longer than the duration"},
           {R"("dt": [0.1], "dt": [0.2], "reference": "closed_form")", "dt: given twice"},
       }) {
    const std::string path = spec(fields);
    expectRefused(loadSweepSpec(path, registry_), path, field);
  }
}

// The grid is counted before it is expanded: 120000 cases are refused at once, naming the
// count and the bound, not expanded into gigabytes first.
TEST_F(InputFiles, AGridOfMoreThanTheBoundIsRefusedBeforeItIsExpanded) {
  std::string scales;
  for (int k = 0; k < 60000; ++k) scales += (k ? "," : "") + std::to_string(1.0 + k * 1e-6);
  const std::string path = spec(R"("integrators": ["euler", "rk4"], "dt": [0.01], "duration": 1, )"
                                R"("reference": "closed_form", "stiffness_scale": [)" + scales + "]");
  auto r = loadSweepSpec(path, registry_);
  expectRefused(r, path, "the grid has 1.2e+05 cases; a spec may have at most 100000");
}

TEST_F(InputFiles, ADirectoryGivenAsAnyInputIsRefusedAsSuch) {
  auto sweep = loadSweepSpec(dir_.string(), registry_);
  ASSERT_FALSE(sweep);
  EXPECT_NE(sweep.error().find("is a directory (expected a sweep spec)"), std::string::npos);
  auto tolerances = loadTolerances(dir_.string(), registry_);
  ASSERT_FALSE(tolerances);
  EXPECT_NE(tolerances.error().find("is a directory"), std::string::npos);
  auto engines = registry_.addEnginesFile(dir_.string());
  ASSERT_FALSE(engines);
  EXPECT_NE(engines.error().find("is a directory"), std::string::npos);
}

TEST_F(InputFiles, ToleranceBoundBeyondTheDoubleRangeIsRefusedNamingTheCheck) {
  const std::string path = file("tol.json", R"({"scene_root": ")" + kRoot + R"(", "checks": [
      {"scene": "scenes/seed/circle.json", "engines": ["mysim"], "metric": "closed_form_error",
       "bound": 1e400, "why": "w"}]})");
  auto t = loadTolerances(path, registry_);
  ASSERT_FALSE(t);
  EXPECT_NE(t.error().find(path + ": checks[0].bound: expected a number within the double range"),
            std::string::npos)
      << t.error();
}

TEST_F(InputFiles, EnginesFileTimeLimitBeyondTheDoubleRangeIsRefused) {
  const std::string path =
      file("e.json", R"({"engines": [{"name": "a", "command": ["x"], "time_limit": 1e999}]})");
  auto added = registry_.addEnginesFile(path);
  ASSERT_FALSE(added);
  EXPECT_NE(added.error().find("engines[0].time_limit"), std::string::npos) << added.error();
}

TEST(Csv, FieldsWithCommasQuotesAndLineBreaksSurviveTheRoundTrip) {
  const std::vector<std::string> fields = {"plain", "a,b", "say \"hi\"", "two\nlines", ""};
  auto back = parseCsvLine(csvLine(fields));
  ASSERT_TRUE(back);
  ASSERT_EQ(back->size(), fields.size());
  EXPECT_EQ((*back)[1], "a,b");
  EXPECT_EQ((*back)[2], "say \"hi\"");
  EXPECT_EQ((*back)[3], "two lines");         // one row stays one line
  EXPECT_FALSE(parseCsvLine("1,\"cut sho"));  // a row cut inside a quoted field
}

TEST_F(InputFiles, ASweepOverAScenePathWithACommaResumesWithoutRerunning) {
  fs::create_directories(dir_ / "a,b");
  fs::copy_file(kRoot + "/scenes/seed/circle.json", dir_ / "a,b" / "circle.json");
  const std::string path = file("spec.json", R"({"scenes": ["a,b/circle.json"],
      "integrators": ["euler", "rk4"], "dt": [0.1], "duration": 1.0, "reference": "closed_form"})");
  auto s = loadSweepSpec(path, registry_);
  ASSERT_TRUE(s) << s.error();
  const std::string table = (dir_ / "t.csv").string();
  ASSERT_EQ(*runSweep(registry_, *s, table, {}), 2);
  auto rows = readSweepTable(table);
  ASSERT_TRUE(rows) << rows.error();
  EXPECT_NE((*rows)[0].c.scene.find("a,b/circle.json"), std::string::npos);
  EXPECT_EQ(*runSweep(registry_, *s, table, {}), 0);  // both rows kept: nothing runs again
}

// A JSON text with bytes that are not UTF-8 (a log line, a file name): written with them
// replaced, not thrown (nlohmann's type_error.316); and a writer that throws anyway leaves the
// previous file and no temporary beside it.
TEST_F(InputFiles, AJsonWriteWithInvalidUtf8IsWholeAndAThrowingWriterLeavesNoTemporary) {
  const std::string path = (dir_ / "summary.json").string();
  const nlohmann::json j = {{"note", std::string("engine said \xff\xfe")}};
  ASSERT_TRUE(writeFileAtomically(path, [&](std::ostream& out) { out << jsonText(j, 2); }));
  std::ifstream in(path);
  const nlohmann::json back = nlohmann::json::parse(in);
  EXPECT_EQ(back["note"].get<std::string>(), "engine said \xef\xbf\xbd\xef\xbf\xbd");
  auto thrown = writeFileAtomically(path, [&](std::ostream& out) { out << j.dump(2); });
  ASSERT_FALSE(thrown);
  EXPECT_NE(thrown.error().find(path), std::string::npos) << thrown.error();
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir_)) files += entry.is_regular_file();
  EXPECT_EQ(files, 1);  // the previous summary.json only
}

TEST_F(InputFiles, AnUnwritablePathIsAnErrorAndLeavesNothing) {
  auto written = writeFileAtomically((dir_ / "no" / "such" / "f.txt").string(),
                                     [](std::ostream& out) { out << "x"; });
  ASSERT_FALSE(written);
  EXPECT_NE(written.error().find("cannot write"), std::string::npos);
  EXPECT_TRUE(fs::is_empty(dir_));
}

}  // namespace
}  // namespace springcheck

namespace springcheck {
namespace {

// A row cut short (no line break after it: the writer was killed mid-line) is not taken as done,
// even when it has every column.
TEST(SweepTable, ALastLineWithoutItsLineBreakIsDroppedAsCutShort) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("springcheck_cut_" + std::to_string(::getpid()) + ".csv");
  SweepRow row;
  row.status = "ok";
  SweepRow cut = row;
  cut.c.id = 1;
  cut.note = "note cut her";
  std::ofstream(path) << csvLine(sweepColumns()) << '\n'
                      << sweepLine(row) << '\n'
                      << sweepLine(cut);
  auto rows = readSweepTable(path.string());
  ASSERT_TRUE(rows) << rows.error();
  ASSERT_EQ(rows->size(), 1u);
  EXPECT_EQ((*rows)[0].c.id, 0);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace springcheck
