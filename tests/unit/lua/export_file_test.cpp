// code_aster .export files: units, limits, refusals with their line; and how verify treats
// .comm/.export cases (collection, output folders, the CODE_ASTER comparison lines).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/core/error.hpp"
#include "lua/export_file.hpp"
#include "lua/verify.hpp"

using namespace lunaster;
using namespace lunaster::lua;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  fs::path dir = fs::path(LUNASTER_BINARY_DIR) / "unit-scratch" / "export" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

/// The message of the DeckError that reading `text` as an .export raises ("" if none).
std::string export_error(const std::string& text) {
  const fs::path dir = scratch("error");
  write(dir / "case.comm", "DEBUT()\n");
  write(dir / "mesh.med", "");
  try {
    read_export(write(dir / "case.export", text));
  } catch (const DeckError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ExportFile, ReadsUnitsLimitsAndIgnoredParameters) {
  const fs::path dir = scratch("units");
  fs::create_directories(dir / "meshes");
  write(dir / "case.comm", "DEBUT()\n");
  write(dir / "meshes" / "m.med", "");
  const auto study = read_export(write(dir / "case.export",
                                       "P time_limit 60\n"
                                       "P memory_limit 512.5\n"
                                       "P testlist verification sequential\n"
                                       "A memjeveux 64\n"
                                       "\n"
                                       "F comm case.comm D 1\n"
                                       "F mmed meshes/m.med D 20\n"
                                       "F rmed case.rmed R 80\n"
                                       "F mess case.mess R 6\n"));
  EXPECT_EQ(study.comm, dir / "case.comm");
  ASSERT_EQ(study.data.size(), 1u);
  EXPECT_EQ(study.data.at(20).type, "mmed");
  EXPECT_EQ(study.data.at(20).path, dir / "meshes" / "m.med");
  EXPECT_EQ(study.data.at(20).line, 7);
  ASSERT_EQ(study.results.size(), 2u);
  EXPECT_EQ(study.results.at(80).type, "rmed");
  EXPECT_EQ(study.results.at(6).type, "mess");
  EXPECT_DOUBLE_EQ(*study.budget.seconds, 60.0);
  EXPECT_DOUBLE_EQ(*study.budget.megabytes, 512.5);
  ASSERT_EQ(study.ignored.size(), 2u);
  EXPECT_EQ(study.ignored[0], "P testlist");
  EXPECT_EQ(study.ignored[1], "A memjeveux");
}

TEST(ExportFile, RefusesWhatItCannotHonourNamingTheLine) {
  const std::string comm = "F comm case.comm D 1\n";
  auto expect = [&](const std::string& text, const std::string& where, const std::string& what) {
    const std::string message = export_error(text);
    EXPECT_NE(message.find(where), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  };
  expect(comm + "F mgib mesh.mgib D 19\n", "case.export:2: ", "convert it to MED");
  expect(comm + "F base base R 0\n", "case.export:2: ", "POURSUITE is not supported");
  expect(comm + "F libr data.txt D 33\n", "case.export:2: ", "lunaster reads the file types comm (D), mmed (D)");
  expect(comm + "F mmed mesh.med D 20\nF rmed out.rmed R 20\n", "case.export:3: ", "unit 20 is given twice; first on line 2");
  expect(comm + "F mmed missing.med D 20\n", "case.export:2: ", "data file");
  expect(comm + "F rmed out.rmed D 80\n", "case.export:2: ", "expected direction R, got 'D'");
  expect(comm + "F mmed mesh.med D twenty\n", "case.export:2: ", "expected a unit number 0..99, got 'twenty'");
  expect(comm + "P time_limit -3\n", "case.export:2: ", "P time_limit: expected a positive number of seconds, got '-3'");
  expect(comm + "P memory_limit 1\nP memory_limit 2\n", "case.export:3: ", "P memory_limit is given twice");
  expect(comm + comm, "case.export:2: ", "a second command file; the first is on line 1");
  expect("F comm case.comm D 2\n", "case.export:1: ", "the command file is unit 1, got unit 2");
  expect("P time_limit 60\n", "case.export: ", "no command file");
  expect(comm + "R repe dir D 0\n", "case.export:2: ", "directory units ('R' lines) are not supported");
  expect(comm + "X what\n", "case.export:2: ", "expected a 'P', 'A' or 'F' line");
  // Files code_aster's tests hand to the study that lunaster cannot read: each named with its line,
  // and what to do.
  const std::pair<const char*, const char*> needed[] = {
      {"F mgib mesh.mgib D 19", "file type 'mgib' (unit 19) is not supported"},
      {"F mgib mesh.mgib D 19", "a Gibi mesh, which code_aster reads with PRE_GIBI"},
      {"F msup mesh.msup D 19", "an I-DEAS universal mesh"},
      {"F libr table.txt D 38", "a data file the study reads on its unit"},
      {"F nom module.py D 0", "a file the study opens by its name"},
      {"F com1 more.comm D 1", "continuation command files (POURSUITE)"},
  };
  for (const auto& [line, what] : needed) expect(comm + line + "\n", "case.export:2: ", what);
  // The skipped types are not offered as types lunaster reads.
  EXPECT_EQ(export_error(comm + "F mgib m.mgib D 19\n").find("datg"), std::string::npos);
  EXPECT_EQ(export_error(comm + "F mmed mesh.med D 20\n# a comment\n"), "");
}

TEST(ExportFile, SkipsTheFilesTheStudyNeverReadsAndReadsMedAsMmed) {
  const fs::path dir = scratch("skipped");
  write(dir / "case.comm", "DEBUT()\n");
  write(dir / "m.med", "");
  // The mesh-generation script need not be there: it is never opened.
  const auto study = read_export(write(dir / "case.export",
                                       "F comm case.comm D 1\n"
                                       "F datg case.datg D 16\n"
                                       "F med m.med D 20\n"
                                       "F datg other.datg D 20\n"));
  ASSERT_EQ(study.skipped.size(), 2u);
  EXPECT_EQ(study.skipped[0].type, "datg");
  EXPECT_EQ(study.skipped[0].line, 2);
  EXPECT_EQ(study.skipped[0].path, dir / "case.datg");
  EXPECT_EQ(study.skipped[1].line, 4);
  // A skipped file binds no unit: unit 20 is the mesh's, and LIRE_MAILLAGE reads it as a MED mesh.
  ASSERT_EQ(study.data.size(), 1u);
  EXPECT_EQ(study.data.at(20).type, "mmed");
  EXPECT_EQ(study.data.at(20).line, 3);
  EXPECT_TRUE(study.results.empty());
}

TEST(ExportFile, BindsCodeAsterTextMeshesToTheirUnit) {
  const fs::path dir = scratch("mail");
  write(dir / "case.comm", "DEBUT()\n");
  write(dir / "m.mail", "");
  const auto study = read_export(write(dir / "case.export", "F comm case.comm D 1\nF mail m.mail D 21\n"));
  ASSERT_EQ(study.data.size(), 1u);
  EXPECT_EQ(study.data.at(21).type, "mail");
  EXPECT_EQ(study.data.at(21).path, dir / "m.mail");
}

TEST(ExportFile, VerifyRunsAnExportInsteadOfItsCommAndKeepsOutputFoldersApart) {
  const fs::path dir = scratch("collect");
  write(dir / "a.lua", "");
  write(dir / "a.comm", "");
  write(dir / "a.export", "F comm a.comm D 1\n");
  write(dir / "b.comm", "");  // no .export: run on its own
  write(dir / "notes.txt", "");
  const auto decks = collect_decks({dir});
  ASSERT_EQ(decks.size(), 3u);
  EXPECT_EQ(decks[0], dir / "a.export");
  EXPECT_EQ(decks[1], dir / "a.lua");
  EXPECT_EQ(decks[2], dir / "b.comm");
  EXPECT_EQ(deck_out_dir("out", dir / "a.lua"), fs::path("out") / "a");
  EXPECT_EQ(deck_out_dir("out", dir / "a.export"), fs::path("out") / "a.export");
  EXPECT_EQ(deck_out_dir("out", dir / "b.comm"), fs::path("out") / "b.comm");
}

TEST(ExportFile, ComparisonLinesAreReadBackFromTheOutput) {
  const auto comparisons = code_aster_comparisons(
      " OK  ANALYTIQUE     DEPL  O  LAGS_C  refe=-1.000000000e+05  calc=-1.000000000e+05  err=1.0e-12  tol=1.0e-03  RELATIF\n"
      "DIFF CODE_ASTER     DEPL  O  LAGS_C  refe=-1.003510000e+05  calc=-1.000000000e+05  err=3.497e-03  tol=1.000e-06  RELATIF\n"
      "NOOK CODE_ASTER     DEPL  A  DY  [top]  refe=-4.999700000e-02  calc=-5.000000000e-02  err=6.000e-05  tol=1.000e-06  RELATIF\n");
  ASSERT_EQ(comparisons.size(), 2u);
  EXPECT_EQ(comparisons[0].check, "DEPL  O  LAGS_C");
  EXPECT_DOUBLE_EQ(comparisons[0].code_aster, -1.00351e5);
  EXPECT_DOUBLE_EQ(comparisons[0].lunaster, -1.0e5);
  EXPECT_DOUBLE_EQ(comparisons[0].difference, 3.497e-3);
  EXPECT_DOUBLE_EQ(comparisons[0].tolerance, 1e-6);
  EXPECT_EQ(comparisons[1].check, "DEPL  A  DY  [top]");
  // Report lines are not checks; CODE_ASTER checks are.
  int ok = 0, nook = 0;
  count_checks("DIFF CODE_ASTER     DEPL  O  LAGS_C  refe=1  calc=2  err=1  tol=1e-06\n"
               "SAME CODE_ASTER     DEPL  A  LAGS_C  refe=1  calc=1  err=0  tol=1e-06\n"
               "NOOK CODE_ASTER     DEPL  B  LAGS_C  refe=1  calc=2  err=1  tol=1e-06\n",
               ok, nook);
  EXPECT_EQ(ok, 0);
  EXPECT_EQ(nook, 1);
}
