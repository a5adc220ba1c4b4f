#include "lua/budget.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <vector>

#include "catalog/args.hpp"
#include "engine/core/error.hpp"
#include "engine/core/memory.hpp"
#include "engine/parallel/mpi_runtime.hpp"
#include "lua/bridge.hpp"

namespace lunaster::lua {

namespace fs = std::filesystem;

namespace {

constexpr double kMegabyte = 1024.0 * 1024.0;
/// Sent by the watchdog to the deck's thread once the budget is spent. SIGURG is ignored by
/// default, so a stray one can do no harm.
constexpr int kBudgetSignal = SIGURG;
/// The Lua state of the deck running under a budget (one at a time per process), for the handler.
std::atomic<lua_State*> budget_state{nullptr};
/// BudgetGuard::grace(), in milliseconds.
std::atomic<long long> grace_ms{BudgetGuard::kGrace.count()};

DeckError header_error(const fs::path& deck, int line, const std::string& key, std::string message,
                       std::vector<std::string> hints = {}) {
  DeckError error(std::move(message), std::move(hints));
  ErrorContext where;
  where.file = deck.string();
  where.line = line;
  where.command = "budget header";
  where.keyword_path = key;
  error.fill_context(where);
  return error;
}

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

const std::vector<std::string> kBudgetKeys = {"time_limit", "memory_limit"};

/// `text` with the blanks around each '=' removed ("time_limit = 60" -> "time_limit=60").
std::string joined_equals(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '=') {
      while (!out.empty() && (out.back() == ' ' || out.back() == '\t')) out.pop_back();
      out += '=';
      while (i + 1 < text.size() && (text[i + 1] == ' ' || text[i + 1] == '\t')) ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

/// Decks also use "-- lunaster: <remark>" comments: a line sets a budget when its first word
/// is KEY=VALUE or a budget key (possibly misspelt, then reported).
bool is_budget_line(const std::string& settings) {
  std::istringstream words(settings);
  std::string first;
  if (!(words >> first)) return false;
  return first.find('=') != std::string::npos || !catalog::closest_name(first, kBudgetKeys).empty();
}

/// Lua instructions hook: once the budget is spent, every Lua step raises an error at the deck line.
void budget_hook(lua_State* L, lua_Debug*) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  const auto* guard = static_cast<const BudgetGuard*>(ud);
  if (!guard->memory_exceeded() && !guard->time_up()) return;
  luaL_where(L, 0);  // a hook runs in the frame of the Lua function it interrupts
  {
    const std::string message = guard->memory_exceeded() ? guard->memory_message() : guard->time_message();
    lua_pushlstring(L, message.data(), message.size());
  }
  lua_concat(L, 2);
  lua_error(L);
}

/// On the deck's thread: from now on every Lua instruction calls budget_hook. Setting a hook
/// from a signal handler is what lua.c does for Ctrl-C; no hook costs nothing before that
/// (a count hook set from the start slows pure Lua code about four times).
void on_budget_signal(int) {
  const int saved = errno;
  if (lua_State* L = budget_state.load()) lua_sethook(L, budget_hook, LUA_MASKCOUNT, 1);
  errno = saved;
}

void install_signal_handler() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction action {};
    action.sa_handler = on_budget_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(kBudgetSignal, &action, nullptr);
  });
}

}  // namespace

std::optional<double> parse_budget_value(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value) || value <= 0.0) return std::nullopt;
  return value;
}

std::string budget_text(double value) {
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

Budget read_budget_header(const fs::path& deck) {
  Budget budget;
  std::ifstream in(deck);
  if (!in) return budget;
  std::string raw;
  int number = 0, time_line = 0, memory_line = 0;
  bool in_header = true;
  while (std::getline(in, raw)) {
    ++number;
    const std::string text = trim(raw);
    const bool comment = text.rfind("--", 0) == 0;
    if (!comment) {
      // Blank lines and a first "#!" line (which Lua skips) keep the header block open.
      if (!text.empty() && !(number == 1 && text[0] == '#')) in_header = false;
      continue;
    }
    const std::string body = trim(text.substr(2));
    if (body.rfind("lunaster:", 0) != 0) continue;
    const std::string settings = joined_equals(body.substr(9));
    if (!is_budget_line(settings)) continue;  // "-- lunaster: largest error 1e-14": a remark
    if (!in_header)
      throw header_error(deck, number, "",
                         "expected the '-- lunaster:' budget line in the comment block at the top of the deck, "
                         "got it below the first line of code");
    std::istringstream words(settings);
    std::string word;
    while (words >> word) {
      const auto equal = word.find('=');
      const std::string key = word.substr(0, equal);
      const bool is_time = key == "time_limit", is_memory = key == "memory_limit";
      if (equal == std::string::npos || !(is_time || is_memory)) {
        std::vector<std::string> hints;
        std::string suggestion = catalog::closest_name(key, kBudgetKeys);
        if (!suggestion.empty()) hints.push_back("did you mean '" + suggestion + "'?");
        throw header_error(deck, number, "", "expected time_limit=SECONDS or memory_limit=MB, got '" + word + "'",
                           std::move(hints));
      }
      int& seen = is_time ? time_line : memory_line;
      if (seen)
        throw header_error(deck, number, key,
                           "expected one value, got a second one (the first is on line " + std::to_string(seen) + ")");
      seen = number;
      const std::string text_value = word.substr(equal + 1);
      const auto value = parse_budget_value(text_value);
      if (!value)
        throw header_error(deck, number, key,
                           std::string("expected a positive number of ") + (is_time ? "seconds" : "MB") + ", got '" +
                               text_value + "'");
      (is_time ? budget.seconds : budget.megabytes) = *value;
    }
  }
  return budget;
}

Budget override_budget(Budget base, const Budget& over) {
  if (over.seconds) base.seconds = over.seconds;
  if (over.megabytes) base.megabytes = over.megabytes;
  return base;
}

double default_memory_budget_mb() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 4096.0;  // unknown machine: 4 GB
  return std::floor(static_cast<double>(pages) * static_cast<double>(page_size) / kMegabyte / 2.0);
}

std::chrono::steady_clock::time_point process_start() {
  const auto now = std::chrono::steady_clock::now();
  std::ifstream stat("/proc/self/stat");
  std::string text;
  std::getline(stat, text);
  const auto name_end = text.rfind(')');  // the command name, in parentheses, may hold blanks
  if (name_end == std::string::npos) return now;
  std::istringstream fields(text.substr(name_end + 1));
  std::string skipped;
  for (int field = 3; field < 22; ++field) fields >> skipped;  // state (3) to itrealvalue (21)
  unsigned long long start_ticks = 0;  // field 22: clock ticks after boot (CLOCK_BOOTTIME)
  timespec boot{};
  const long ticks_per_second = sysconf(_SC_CLK_TCK);
  if (!(fields >> start_ticks) || ticks_per_second <= 0 || clock_gettime(CLOCK_BOOTTIME, &boot) != 0) return now;
  // The start is kept in whole ticks, rounded down: count from the tick's end, so that a limit
  // never falls early (it may fall up to a tick late).
  const double age = static_cast<double>(boot.tv_sec) + 1e-9 * static_cast<double>(boot.tv_nsec) -
                     static_cast<double>(start_ticks + 1) / static_cast<double>(ticks_per_second);
  if (!(age > -1.0) || age > 86400.0) return now;  // unreadable, or not this run's process
  return now - std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                   std::chrono::duration<double>(std::max(age, 0.0)));
}

void BudgetGuard::set_grace(std::chrono::milliseconds grace) { grace_ms = grace.count(); }

std::chrono::milliseconds BudgetGuard::grace() { return std::chrono::milliseconds(grace_ms.load()); }

BudgetGuard::BudgetGuard(const Budget& budget, std::string deck, std::chrono::steady_clock::time_point start)
    : budget_(budget), deck_(std::move(deck)), deck_thread_(pthread_self()), grace_(grace()) {
  using clock = std::chrono::steady_clock;
  if (budget_.seconds)
    deadline_ = start + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(*budget_.seconds));
  lua_cap_ = static_cast<std::size_t>(-1);
  if (budget_.megabytes) {
    memory_bytes_ = static_cast<std::size_t>(*budget_.megabytes * kMegabyte);
    // The Lua heap may take the process up to the budget from where it stands now.
    const std::size_t now = engine::resident_bytes();
    lua_cap_ = memory_bytes_ > now ? memory_bytes_ - now : 0;
    engine::set_memory_budget(memory_bytes_);  // what the solvers may plan for (MUMPS's AUTO)
  }
  if (budget_.seconds || budget_.megabytes) watchdog_ = std::thread([this] { watch(); });
}

BudgetGuard::~BudgetGuard() { stop(); }

void BudgetGuard::stop() {
  {
    std::lock_guard<std::mutex> lock(watch_mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (watchdog_.joinable()) watchdog_.join();
  if (budget_.megabytes) engine::set_memory_budget(0);
  // A deck that ends past its deadline (the last command finished during the grace) is over budget.
  if (budget_.seconds && std::chrono::steady_clock::now() >= deadline_) time_up_ = true;
}

void BudgetGuard::install(lua_State* L) {
  if (!budget_.seconds && !budget_.megabytes) return;
  lua_bytes_ = static_cast<std::size_t>(lua_gc(L, LUA_GCCOUNT, 0)) * 1024 +
               static_cast<std::size_t>(lua_gc(L, LUA_GCCOUNTB, 0));
  // luaL_newstate's allocator is realloc/free as well: blocks already allocated stay valid.
  lua_setallocf(L, &BudgetGuard::allocate, this);
  install_signal_handler();
  budget_state = L;
  if (time_up() || memory_exceeded()) lua_sethook(L, budget_hook, LUA_MASKCOUNT, 1);  // spent already
}

void BudgetGuard::uninstall(lua_State* L) {
  lua_State* expected = L;
  budget_state.compare_exchange_strong(expected, nullptr);
}

void* BudgetGuard::allocate(void* ud, void* ptr, std::size_t osize, std::size_t nsize) {
  auto* guard = static_cast<BudgetGuard*>(ud);
  const std::size_t old = ptr ? osize : 0;  // without a block, osize is the type of object
  if (nsize == 0) {
    std::free(ptr);
    guard->lua_bytes_ -= old;
    return nullptr;
  }
  if (guard->in_protected_call_ && nsize > old && guard->lua_bytes_ - old + nsize > guard->lua_cap_) {
    guard->memory_exceeded_ = true;
    return nullptr;  // Lua collects garbage, retries, then raises "not enough memory"
  }
  void* block = std::realloc(ptr, nsize);
  if (!block) return nullptr;  // the machine's memory: Lua raises "not enough memory"
  guard->lua_bytes_ = guard->lua_bytes_ - old + nsize;
  return block;
}

std::string BudgetGuard::time_message() const {
  return "time limit of " + budget_text(budget_.seconds.value_or(0.0)) + " s exceeded";
}

std::string BudgetGuard::memory_message() const {
  return "memory limit of " + budget_text(budget_.megabytes.value_or(0.0)) + " MB exceeded";
}

void BudgetGuard::set_running(const std::string& where) {
  std::lock_guard<std::mutex> lock(running_mutex_);
  running_ = where;
}

void BudgetGuard::watch() {
  const auto grace_end = deadline_ + grace_;
  bool signalled = false;
  std::unique_lock<std::mutex> lock(watch_mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, kSample);
    if (stopping_) break;
    const auto now = std::chrono::steady_clock::now();
    if (budget_.seconds && now >= deadline_) {
      time_up_ = true;
      if (now >= grace_end) hard_stop(static_cast<int>(ErrorKind::TimeLimit), time_message());
    }
    if (budget_.megabytes) {
      const std::size_t resident = engine::resident_bytes();
      if (resident > memory_bytes_) {
        memory_exceeded_ = true;
        hard_stop(static_cast<int>(ErrorKind::OutOfMemory),
                  memory_message() + " (resident memory " + budget_text(std::round(resident / kMegabyte)) + " MB)");
      }
    }
    if (!signalled && (time_up_ || memory_exceeded_)) {
      pthread_kill(deck_thread_, kBudgetSignal);  // the deck's Lua code stops at its next instruction
      signalled = true;
    }
  }
}

void BudgetGuard::hard_stop(int exit_code, const std::string& what) {
  std::string running;
  {
    std::unique_lock<std::mutex> lock(running_mutex_, std::try_to_lock);
    if (lock.owns_lock()) running = running_;
  }
  std::string message = deck_ + ": " + what;
  message += running.empty() ? " in the deck's Lua code" : " while running " + running;
  message += "; the run is stopped\n";
  // Under mpirun the stop ends every rank (MPI_Abort): none is left waiting in a collective
  // call for this one. Rank 0 speaks; the others, silenced, speak only when they are the ones
  // stopping the run: past a time limit, which every rank reaches at about the same moment,
  // they leave rank 0 a moment to stop the run first.
  if (const int rank = engine::parallel::rank(); rank > 0) {
    if (exit_code == static_cast<int>(ErrorKind::TimeLimit)) std::this_thread::sleep_for(kOtherRanksDelay);
    message = "lunaster: rank " + std::to_string(rank) + ": " + message;
  }
  // Keep what the deck printed so far, unless the main thread is inside stdout right now.
  if (ftrylockfile(stdout) == 0) {
    std::fflush(stdout);
    funlockfile(stdout);
  }
  const char* data = message.data();
  std::size_t left = message.size();
  const int fd = engine::parallel::standard_error_fd();  // a silenced rank's own, kept for this
  while (left > 0) {
    const ssize_t n = write(fd, data, left);
    if (n <= 0) break;
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  engine::parallel::abort_run(exit_code);  // _exit in a one-rank run
}

}  // namespace lunaster::lua
