// DEBUT and FIN: start and end of a deck (kept for code_aster readers); DEBUT's MESURE_TEMPS
// asks for the time report of the nonlinear commands.
#include <cmath>
#include <cstdio>
#include <vector>

#include "commands/commands.hpp"
#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

ConceptPtr debut(const Args& args, Session& session) {
  session.time_report_level = 0;
  session.time_report_over_ranks = false;
  if (args.count("MESURE_TEMPS") == 0) return nullptr;
  const Args m = args.factor("MESURE_TEMPS");
  const long long level = m.integer("NIVE_DETAIL");
  if (level == 3)
    throw m.error("NIVE_DETAIL", "0, 1 or 2 (the times of whole commands)", "3",
                  {"code_aster's level 3 reports the times of every time step: lunaster measures a nonlinear "
                   "command as a whole, and NIVE_DETAIL = 2 gives the same phases with the counts of its steps"});
  session.time_report_level = static_cast<int>(level);
  session.time_report_over_ranks = m.text("MOYENNE") == "OUI";
  return nullptr;
}

namespace {

/// "name  t s" on rank 0's clock, or with MOYENNE = 'OUI' "name  mean s (standard deviation s over N ranks)".
std::vector<std::string> time_lines(const std::vector<std::pair<std::string, double>>& times, bool over_ranks) {
  std::vector<double> mine;
  for (const auto& t : times) mine.push_back(t.second);
  const std::vector<double> all = over_ranks ? engine::parallel::gather_all(mine) : mine;
  const size_t n = times.size(), ranks = all.size() / n;
  std::vector<std::string> lines;
  for (size_t i = 0; i < n; ++i) {
    double mean = 0.0, square = 0.0;
    for (size_t r = 0; r < ranks; ++r) mean += all[r * n + i] / static_cast<double>(ranks);
    for (size_t r = 0; r < ranks; ++r) square += std::pow(all[r * n + i] - mean, 2) / static_cast<double>(ranks);
    char buf[160];
    if (over_ranks)
      std::snprintf(buf, sizeof buf, "    %-16s %10.3f s (standard deviation %.3f s over %zu rank(s))", times[i].first.c_str(),
                    mean, std::sqrt(square), ranks);
    else
      std::snprintf(buf, sizeof buf, "    %-16s %10.3f s", times[i].first.c_str(), mean);
    lines.emplace_back(buf);
  }
  return lines;
}

}  // namespace

void report_times(Session& session, const engine::SolverStats& st, double wall_seconds) {
  if (session.time_report_level <= 0) return;
  const std::vector<std::string> lines =
      time_lines({{"total", wall_seconds},
                  {"assembly", st.assemble_seconds},
                  {"contact", st.contact_seconds},
                  {"factorisation", st.factorize_seconds},
                  {"solve", st.solve_seconds}},
                 session.time_report_over_ranks);
  Log& log = session.log();
  log.info("  time of the command (MESURE_TEMPS, wall clock):");
  for (const auto& line : lines) log.info(line);
  if (session.time_report_level < 2) return;
  log.info("    " + std::to_string(st.instants) + " instant(s), " + std::to_string(st.newton_iterations) +
           " Newton iteration(s), " + std::to_string(st.factorisations) + " factorisation(s), " +
           std::to_string(st.contact_passes) + " contact pass(es), " + std::to_string(st.refinement_steps) +
           " refinement step(s), " + std::to_string(st.n_dofs) + " unknowns");
}

ConceptPtr fin(const Args&, Session& session) {
  session.fin_called = true;
  return nullptr;
}

}  // namespace lunaster::cmd
