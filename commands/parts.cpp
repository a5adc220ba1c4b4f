#include "commands/parts.hpp"

#include <new>
#include <vector>

#include "engine/parallel/mpi_runtime.hpp"

namespace lunaster::cmd {

namespace parallel = engine::parallel;

namespace {

struct Requirement {
  bool holds_here = false;
  DeckError error;
};

std::vector<Requirement>& requirements() {
  static std::vector<Requirement> recorded;
  return recorded;
}

/// Set when agree_over_ranks throws: every rank then throws, and the failure is not agreed on
/// again where the command ends (the ranks would not meet there: the one that failed first
/// agreed at the end of its command, the others where they met it).
bool& agreed_failure() {
  static bool flag = false;
  return flag;
}

bool& parts_flag() {
  static bool flag = false;
  return flag;
}

/// An error as bytes: kind, keyword path, message, hints, each ended by a zero byte.
std::string to_bytes(const Error& e) {
  std::string out = std::to_string(static_cast<int>(e.kind())) + '\0' + e.context().keyword_path + '\0';
  out += e.message() + '\0';
  for (const auto& hint : e.hints()) out += hint + '\0';
  return out;
}

/// The exception `failure` holds, as an Error (the runner's wording for the others).
std::string failure_bytes(std::exception_ptr failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const Error& e) {
    return to_bytes(e);
  } catch (const std::bad_alloc&) {
    return to_bytes(Error(ErrorKind::OutOfMemory, "out of memory: the machine refused an allocation"));
  } catch (const std::exception& e) {
    return to_bytes(InternalError(std::string("unexpected exception: ") + e.what()));
  } catch (...) {
    return to_bytes(InternalError("unknown exception"));
  }
}

[[noreturn]] void throw_bytes(const std::string& bytes, int rank) {
  std::vector<std::string> parts;
  for (size_t at = 0; at < bytes.size();) {
    const size_t end = bytes.find('\0', at);
    parts.push_back(bytes.substr(at, end - at));
    at = end + 1;
  }
  if (parts.size() < 3) throw InternalError("a rank's error arrived garbled");
  const auto kind = static_cast<ErrorKind>(std::stoi(parts[0]));
  std::vector<std::string> hints(parts.begin() + 3, parts.end());
  hints.push_back("found by rank " + std::to_string(rank) + " on its part of the mesh");
  ErrorContext where;
  where.keyword_path = parts[1];
  if (kind == ErrorKind::Deck) {
    DeckError e(parts[2], hints);
    e.fill_context(where);
    throw e;
  }
  if (kind == ErrorKind::Solve) {
    SolveError e(parts[2], hints);
    e.fill_context(where);
    throw e;
  }
  Error e(kind, parts[2], hints);
  e.fill_context(where);
  throw e;
}

}  // namespace

namespace {
const char* const kTakingParts[] = {"DEFI_GROUP",    "MODI_MAILLAGE", "AFFE_MODELE",  "AFFE_MATERIAU", "AFFE_CHAR_MECA",
                                    "DEFI_CONTACT",  "DEFI_CONT",     "STAT_NON_LINE", "MECA_NON_LINE", "CALC_CHAMP",
                                    "TEST_RESU",     "IMPR_RESU",     "IMPR_MESURE",   "POST_RELEVE_T"};
}  // namespace

bool takes_parts(const std::string& command) {
  for (const char* name : kTakingParts)
    if (command == name) return true;
  return false;
}

std::string commands_taking_parts() {
  std::string out;
  for (const char* name : kTakingParts) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

bool parts_in_run() { return parts_flag(); }
void set_parts_in_run(bool on) { parts_flag() = on; }

void forget_requirements() {
  requirements().clear();
  agreed_failure() = false;
}

void require_somewhere(const engine::Mesh& mesh, bool holds_here, const DeckError& error) {
  if (!mesh.is_part) {
    if (!holds_here) throw error;
    return;
  }
  requirements().push_back({holds_here, error});
}

void agree_over_ranks(std::exception_ptr failure) {
  if (!parts_in_run()) {
    forget_requirements();
    if (failure) std::rethrow_exception(failure);
    return;
  }
  if (failure && agreed_failure()) std::rethrow_exception(failure);
  std::vector<Requirement> recorded;
  recorded.swap(requirements());
  agreed_failure() = true;  // until it returns: whatever it throws was agreed on
  // A rank that failed may have recorded fewer requirements: the ones every rank reached are
  // decided, in order, before any failure (a name no part holds explains the failures it causes).
  const double count = static_cast<double>(recorded.size());
  const long long common = static_cast<long long>(-parallel::max_over_ranks(-count));
  std::vector<double> held(static_cast<size_t>(common));
  for (long long k = 0; k < common; ++k) held[k] = recorded[k].holds_here ? 1.0 : 0.0;
  parallel::sum_over_ranks(held.data(), common);
  for (long long k = 0; k < common; ++k)
    if (held[k] == 0.0) throw recorded[k].error;
  const int rank = parallel::rank();
  const double lowest = -parallel::max_over_ranks(failure ? -static_cast<double>(rank) : -1e9);
  if (lowest > 1e8) {
    agreed_failure() = false;
    return;
  }
  const int failing = static_cast<int>(lowest);
  std::string bytes = rank == failing ? failure_bytes(failure) : std::string();
  parallel::broadcast_from(failing, bytes);
  if (rank == failing) std::rethrow_exception(failure);
  throw_bytes(bytes, failing);
}

}  // namespace lunaster::cmd
