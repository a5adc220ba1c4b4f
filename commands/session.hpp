#pragma once
/// Per-run context handed to every command: the log, run options, where the
/// deck and output live, the TEST_RESU report and phase timers. It holds no
/// model data: commands take explicit inputs and return new concepts.
#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"

namespace lunaster::cmd {

/// One TEST_RESU check as reported.
struct TestLine {
  bool ok = false;
  std::string text;  ///< the printed line
};

class Session {
 public:
  explicit Session(Log& log) : log_(log) {}

  Log& log() { return log_; }
  const Log& log() const { return log_; }

  std::filesystem::path deck_path;   ///< the deck being run
  std::filesystem::path output_dir;  ///< where output files go (created on demand)
  /// Resolves a path given in a deck: relative paths are relative to the deck's folder.
  std::filesystem::path resolve_input(const std::string& relative) const;
  /// Path of an output file in output_dir (the folder is created, by rank 0 under mpirun).
  std::filesystem::path output_file(const std::string& name) const;
  /// The output file of logical unit `unit` with extension `ext`: the file an .export binds to
  /// the unit (its name, in output_dir), else <deck name>_<unit>.<ext>.
  std::filesystem::path unit_output_file(int unit, const std::string& ext) const;

  /// Location of the command being run (for warnings and errors).
  ErrorContext current;
  /// Logs a warning prefixed with the current deck location and command.
  void warn(const std::string& message);

  // ---- TEST_RESU report ----
  std::vector<TestLine> tests;
  int n_ok() const;
  int n_nook() const;

  // ---- phase timers (seconds), e.g. "read", "assemble", "solve" ----
  std::map<std::string, double> phase_seconds;
  class Timer {
   public:
    Timer(Session& s, std::string phase) : s_(s), phase_(std::move(phase)), t0_(std::chrono::steady_clock::now()) {}
    ~Timer() { s_.phase_seconds[phase_] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count(); }
   private:
    Session& s_;
    std::string phase_;
    std::chrono::steady_clock::time_point t0_;
  };

  // ---- IMPR_MESURE: the phase times and clock at its previous call ----
  std::map<std::string, double> phase_seconds_measured;
  std::chrono::steady_clock::time_point measure_mark = std::chrono::steady_clock::now();

  bool fin_called = false;

  /// DEBUT MESURE_TEMPS: NIVE_DETAIL of the time report after each nonlinear command (0: none),
  /// and MOYENNE = 'OUI' (each time as its mean and standard deviation over the ranks).
  int time_report_level = 0;
  bool time_report_over_ranks = false;

  /// Files IMPR_TABLE wrote in this run: a further table on the same file is appended, as on
  /// a code_aster unit.
  std::set<std::filesystem::path> table_files;

  // ---- code_aster studies: units of an .export, VALE_CALC of a .comm ----
  /// A file bound to a logical unit by an .export (`F mmed mesh.med D 20`).
  struct UnitFile {
    std::string type;  ///< mmed, msh (read); rmed, resu, mess (written)
    std::filesystem::path path;
  };
  /// The .export of the run (empty for a deck run on its own): LIRE_MAILLAGE and IMPR_RESU
  /// then take their UNITE from `data_units` / `result_units` instead of the deck's name.
  std::filesystem::path export_path;
  std::map<int, UnitFile> data_units;
  std::map<int, UnitFile> result_units;
  /// The deck is a code_aster .comm: its VALE_CALC are code_aster's results, so TEST_RESU
  /// reports them as comparisons with code_aster (kind CODE_ASTER).
  bool code_aster_vale_calc = false;
  /// ... and, with `--vale-calc=report`, prints those comparisons without counting them as
  /// checks (the VALE_REFE checks alone decide OK/NOOK).
  bool vale_calc_report = false;
  /// `--solveur=MUMPS` on the command line: every STAT_NON_LINE factorises with MUMPS, the model
  /// shared among the ranks under mpirun, whatever its SOLVEUR says (empty: the deck decides).
  std::string solveur_override;
  /// One comparison of a .comm's VALE_CALC (code_aster's value) with lunaster's.
  struct Comparison {
    std::string what;
    double lunaster = 0.0, code_aster = 0.0, difference = 0.0, tolerance = 0.0;
  };
  std::vector<Comparison> comparisons;

 private:
  Log& log_;
};

}  // namespace lunaster::cmd
