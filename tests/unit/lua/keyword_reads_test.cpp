// Every keyword the catalogue accepts is read by its command's handler (STYLE.md §8:
// "every accepted keyword changes something"), or is listed below as accepted for
// documentation/compatibility only, with the reason.
//
// How: the real handlers run every deck of testcases/ (not errors/) in-process through
// the real runner, with Args recording each keyword a handler asks for (has, values,
// count, factor; see catalog::KeywordReads). The catalogue is then walked: each declared
// keyword path ("STAT_NON_LINE/NEWTON/REAC_ITER", children and conditional blocks, at
// every depth) must have been read, or be listed below with the reason: kValidatorOnly
// (a single allowed value, enforced by the validator) or kCompatibilityOnly (accepted for
// code_aster decks, no effect). Adding a keyword to a spec without reading it in the handler
// (or without a deck that reaches the code reading it) fails here; so does a stale entry of
// the lists (a listed keyword that is read, no longer declared, or given a second value).
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "catalog/args.hpp"
#include "catalog/spec.hpp"
#include "commands/registry.hpp"
#include "lua/export_file.hpp"
#include "lua/runner.hpp"
#include "lua/verify.hpp"

namespace fs = std::filesystem;
using namespace lunaster;

namespace {

/// Keywords with a single allowed value, which is what lunaster does: the validator enforces
/// the value and the handler has nothing to choose. The test checks that each still has one
/// allowed value, so adding a second one without reading the keyword fails here.
const std::map<std::string, std::string> kValidatorOnly = {
    {"AFFE_MODELE/AFFE/PHENOMENE", "only 'MECANIQUE', the one phenomenon"},
    {"AFFE_CHAR_MECA/LIAISON_MAIL/TYPE_RACCORD", "only 'MASSIF': solid to solid, the one gluing built"},
    {"CALC_CHAMP/TOUT_ORDRE", "only 'OUI': every step, as when neither NUME_ORDRE nor INST is given"},
    {"POST_RELEVE_T/ACTION/TOUT_ORDRE", "only 'OUI': every step, as when neither NUME_ORDRE nor INST is given"},
    {"IMPR_TABLE/FORMAT", "only 'TABLEAU': the one table format (CSV is TABLEAU with SEPARATEUR)"},
    {"DEFI_FONCTION/INTERPOL", "only 'LIN': functions are piecewise linear"},
    {"DEFI_LIST_INST/DEFI_LIST/METHODE", "only 'MANUEL': the instants are given by LIST_INST"},
    {"DEFI_LIST_INST/ECHEC/EVENEMENT", "only 'ERREUR': a failed step is the one event handled"},
    {"DEFI_LIST_INST/ECHEC/SUBD_METHODE", "only 'MANUEL': a failed step is cut into SUBD_PAS equal steps"},
    {"DEFI_CONTACT/ZONE/APPARIEMENT", "only 'MAIT_ESCL': a slave point is paired with its projection on the master"},
    {"DEFI_CONTACT/ZONE/NORMALE", "only 'MAIT': the projection follows the master surface's normal"},
};

/// Keywords accepted so that code_aster decks run, without effect in lunaster (their catalogue
/// doc says so).
const std::map<std::string, std::string> kCompatibilityOnly = {
    {"DEBUT/CODE", "code_aster test-suite marker; lunaster has no test-suite mode to switch"},
    {"DEBUT/PAR_LOT", "code_aster batch-mode switch; lunaster always runs a deck command by command"},
    {"DEBUT/DEBUG", "code_aster debugging switches; lunaster has no data-structure checks to turn on"},
    {"DEBUT/DEBUG/SDVERI", "code_aster data-structure checks; lunaster has none to turn on"},
    {"DEBUT/DEBUG/JXVERI", "code_aster memory-manager checks; lunaster has no such manager"},
    {"DEBUT/DEBUG/JEVEUX", "code_aster memory-manager debugging; lunaster has no such manager"},
    {"DEBUT/DEBUG/HIST_ETAPE", "code_aster command history; lunaster echoes every command in its log"},
    {"DEBUT/ERREUR", "code_aster error handling; a lunaster error always stops the deck with the reason"},
    {"DEBUT/ERREUR/ERREUR_F", "code_aster's ABORT or EXCEPTION; a lunaster error always stops the deck"},
    {"DEBUT/INFO", "code_aster's print level of DEBUT; lunaster's is set for the run (lunaster run -v / -q)"},
    {"DEBUT/IMPR_MACRO", "code_aster's echo inside macros; lunaster's commands are not macros"},
    {"DEBUT/IGNORE_ALARM", "code_aster alarm identifiers; lunaster's warnings have none"},
    {"DEFI_FONCTION/NOM_RESU", "name of the values in code_aster's function tables; lunaster prints none"},
    {"AFFE_CHAR_MECA/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"AFFE_MODELE/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"CALC_CHAMP/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"CREA_CHAMP/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"POST_RELEVE_T/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"TEST_TABLE/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"DEFI_CONTACT/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"DEFI_CONT/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"DEFI_FONCTION/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"DEFI_GROUP/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"LIRE_MAILLAGE/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"MODI_MAILLAGE/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"DEFI_MATERIAU/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"AFFE_MATERIAU/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"DEFI_LIST_INST/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"IMPR_RESU/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
    {"DEFI_LIST_REEL/INFO", "code_aster's print level; lunaster's is set for the run (lunaster run -v / -q)"},
};

/// Every keyword declared by `spec` under `prefix` (children and block keywords, recursively),
/// by path; a path declared in several blocks (ZONE of DEFI_CONTACT) lists each declaration.
void declared_keywords(const catalog::Keyword& spec, const std::string& prefix,
                       std::map<std::string, std::vector<const catalog::Keyword*>>& out) {
  auto add = [&](const catalog::Keyword& kw) {
    const std::string path = prefix + "/" + kw.name;
    out[path].push_back(&kw);
    if (kw.is_factor) declared_keywords(kw, path, out);
  };
  for (const auto& kw : spec.children) add(kw);
  for (const auto& block : spec.blocks)
    for (const auto& kw : block.keywords) add(kw);
}

/// Runs every verification deck with the real handlers, recording what they read.
catalog::KeywordReads read_by_the_decks() {
  catalog::KeywordReads reads;
  const auto decks = lua::collect_decks({fs::path(LUNASTER_SOURCE_DIR) / "testcases"});
  EXPECT_GT(decks.size(), 10u);
  for (const auto& deck : decks) {
    std::ostringstream sink;
    Log log(sink, 0);
    cmd::Session session(log);
    session.deck_path = deck;
    session.output_dir = fs::path(LUNASTER_BINARY_DIR) / "unit-keyword-reads" / deck.stem();
    try {
      lua::Runner runner(session, cmd::find_handler);
      runner.set_keyword_reads(&reads);
      // testcases/comm holds code_aster studies (.export naming a .comm): run them as `lunaster run` does
      if (lua::is_export_file(deck)) {
        const lua::ExportFile study = lua::read_export(deck);
        lua::apply_export(study, session);
        runner.run_comm(study.comm);
      } else if (lua::is_comm_file(deck)) {
        runner.run_comm(deck);
      } else {
        runner.run_file(deck);
      }
    } catch (const Error& e) {
      ADD_FAILURE() << deck << " failed: " << e.what();
    }
  }
  return reads;
}

TEST(KeywordReads, EveryDeclaredKeywordIsReadByItsHandler) {
  const catalog::KeywordReads reads = read_by_the_decks();
  std::map<std::string, std::vector<const catalog::Keyword*>> declared;
  for (const auto& spec : catalog::all_commands()) declared_keywords(spec.body, spec.name, declared);
  for (const auto& [path, keywords] : declared) {
    const bool read = reads.contains(path);
    const bool listed = kValidatorOnly.count(path) > 0 || kCompatibilityOnly.count(path) > 0;
    EXPECT_TRUE(read || listed) << path
                                << " is accepted by the catalogue but no handler reads it in any deck of testcases/: "
                                   "read it (and give it a deck), refuse it, or list it here with the reason";
    EXPECT_FALSE(read && listed) << path << " is read by its handler: take it off the lists";
  }
  for (const auto& [path, reason] : kValidatorOnly) {
    ASSERT_TRUE(declared.count(path)) << path << " is listed but not declared";
    for (const catalog::Keyword* kw : declared.at(path))
      EXPECT_EQ(kw->into.size(), 1u) << path << " allows several values now: its handler must read it";
    EXPECT_FALSE(reason.empty()) << path;
  }
  for (const auto& [path, reason] : kCompatibilityOnly) {
    EXPECT_TRUE(declared.count(path)) << path << " is listed but not declared";
    EXPECT_FALSE(reason.empty()) << path;
  }
  // Reads are recorded by the same paths the catalogue declares (a sanity check of the recorder).
  for (const auto& path : reads.paths()) EXPECT_TRUE(declared.count(path)) << path << " read but not declared";
}

TEST(KeywordReads, TheRecorderSeesWhatAHandlerAsks) {
  // A handler that reads one keyword of a factor and ignores the rest: the walk above would flag them.
  const catalog::CommandSpec& spec = *catalog::find_command("DEFI_LIST_INST");
  catalog::KwNode node, defi, echec;
  echec.simple["ACTION"] = {std::string("DECOUPE")};
  node.factors["DEFI_LIST"] = {defi};
  node.factors["ECHEC"] = {echec};
  catalog::KeywordReads reads;
  const catalog::Args args(node, spec.body, {}, &reads);
  EXPECT_EQ(args.count("ECHEC"), 1);
  EXPECT_EQ(args.factor("ECHEC").text("ACTION"), "DECOUPE");
  EXPECT_FALSE(args.factor("ECHEC").has("SUBD_PAS"));
  EXPECT_EQ(reads.paths(), (std::set<std::string>{"DEFI_LIST_INST/ECHEC", "DEFI_LIST_INST/ECHEC/ACTION",
                                                   "DEFI_LIST_INST/ECHEC/SUBD_PAS"}));
  EXPECT_FALSE(reads.contains("DEFI_LIST_INST/ECHEC/SUBD_NIVEAU"));
}

}  // namespace
