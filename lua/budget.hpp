#pragma once
/// Time and memory budgets of a deck run, as code_aster's `.export` files give
/// `time_limit` and `memory_limit`: read from the deck header
/// (`-- lunaster: time_limit=60 memory_limit=512`) or the command line, and
/// enforced inside the running process by BudgetGuard.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <pthread.h>

struct lua_State;

namespace lunaster::lua {

/// A budget; an unset field is no limit.
struct Budget {
  std::optional<double> seconds;    ///< wall-clock time of the run, in seconds
  std::optional<double> megabytes;  ///< resident memory of the process, in MB (2^20 bytes)
};

/// The budget declared by `-- lunaster: time_limit=SECONDS memory_limit=MB` lines in the
/// comment block at the top of `deck` (before its first line of code; blanks around '='
/// allowed). A `-- lunaster:` line whose first word is neither KEY=VALUE nor (close to) a
/// budget key is a remark, as the decks' "-- lunaster: largest error ..." lines. A missing
/// or unreadable file has no budget (the runner reports it). Throws DeckError naming the
/// file and line for an unknown key, a value that is not a positive number, a key given
/// twice, or a budget line below the first line of code.
Budget read_budget_header(const std::filesystem::path& deck);
/// `base` with the fields that `over` sets replaced (the command line overrides the header).
Budget override_budget(Budget base, const Budget& over);
/// A positive finite number from `text`, or nullopt.
std::optional<double> parse_budget_value(const std::string& text);
/// Shortest text of a limit ("1", "0.5", "512") for messages and child command lines.
std::string budget_text(double value);
/// Half of the machine's physical memory, in MB: `lunaster verify`'s default memory budget.
double default_memory_budget_mb();
/// Enforces a budget on this process while one deck runs.
///
/// Time: at the deadline a watchdog thread raises a flag and signals the deck's thread,
/// whose handler sets a Lua hook (as lua.c does for Ctrl-C) that raises a Lua error at the
/// deck line being run, at every instruction from then on (so a `while true do end` stops,
/// and pcall cannot keep the deck going). If the process is still running kGrace later (a
/// long C++ solve never returns to Lua), the watchdog prints which command was running and
/// ends the process with exit status 5 (under mpirun: the whole run, every rank). Until the
/// budget is spent, Lua runs without a hook.
///
/// Memory: the Lua allocator refuses to let the Lua heap take the process beyond the
/// budget (a clean "memory limit exceeded" error, then the hook as for time), and the
/// watchdog samples the resident memory every kSample and ends the process with exit
/// status 6 above the budget. No
/// rlimit is set: a limit on address space or data segment also counts thread stacks and
/// reserved arenas (OpenMP, OpenBLAS, malloc) and turns them into failed allocations deep
/// inside libraries; the resident memory is what the budget protects.
/// When this process was created, on the steady clock (the kernel's start time, at the end of
/// its 10 ms clock tick), or now if that cannot be read. `lunaster verify` counts a deck's time
/// limit from the moment it starts the child, so the child counts its own from its creation
/// too: its start (70 libraries to load, much slower under a sanitizer or on a loaded machine)
/// is part of the run, and the run stops itself before verify's kill, one second past the
/// limit. (Not under mpirun: there verify gives mpirun's start-up a grace of its own.)
std::chrono::steady_clock::time_point process_start();

class BudgetGuard {
 public:
  static constexpr std::chrono::milliseconds kGrace{500};
  /// The grace of the guards made from now on: kGrace unless set. A test that runs decks inside
  /// its own process sets it long, so that a loaded machine (the deck's thread not run within
  /// kGrace of the deadline) cannot make the watchdog end the test process before the Lua hook
  /// stops the deck; `lunaster` never sets it.
  static void set_grace(std::chrono::milliseconds grace);
  static std::chrono::milliseconds grace();
  static constexpr std::chrono::milliseconds kSample{20};
  /// Under mpirun, ranks other than 0 stop this much later than rank 0 past a time limit.
  static constexpr std::chrono::milliseconds kOtherRanksDelay{1000};

  /// Starts the watchdog for `budget`; `deck` names the deck in messages. The time limit
  /// counts from `start` (`lunaster run`: process_start(), or the deck's start under mpirun).
  BudgetGuard(const Budget& budget, std::string deck,
              std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now());
  ~BudgetGuard();
  BudgetGuard(const BudgetGuard&) = delete;
  BudgetGuard& operator=(const BudgetGuard&) = delete;

  /// Uses the budget's allocator in `L` (created by luaL_newstate) and hooks it once the
  /// budget is spent; uninstall before closing `L`.
  void install(lua_State* L);
  void uninstall(lua_State* L);
  /// Around the protected call that runs the deck: only there may the allocator refuse a
  /// block (an unprotected refusal is a Lua panic, which aborts the process). Outside it,
  /// the watchdog's resident-memory check still stops a deck over its budget.
  void set_protected(bool on) { in_protected_call_ = on; }
  /// Stops the watchdog (the deck has finished; reporting must not be cut off).
  void stop();

  const Budget& budget() const { return budget_; }
  bool time_up() const { return time_up_.load(); }
  bool memory_exceeded() const { return memory_exceeded_.load(); }
  /// "time limit of 1 s exceeded", "memory limit of 64 MB exceeded".
  std::string time_message() const;
  std::string memory_message() const;
  /// The command being run ("deck.lua:12: STAT_NON_LINE"), empty in Lua code; named by a hard stop.
  void set_running(const std::string& where);

 private:
  static void* allocate(void* ud, void* ptr, std::size_t osize, std::size_t nsize);
  void watch();
  [[noreturn]] void hard_stop(int exit_code, const std::string& what);

  Budget budget_;
  std::string deck_;
  pthread_t deck_thread_;  ///< the thread running the deck (the one that made the guard)
  std::chrono::steady_clock::time_point deadline_;
  std::chrono::milliseconds grace_;  ///< from the deadline to the hard stop
  std::size_t memory_bytes_ = 0;
  std::size_t lua_bytes_ = 0;  ///< Lua heap (main thread only)
  std::size_t lua_cap_ = 0;    ///< the Lua heap may not grow beyond this
  bool in_protected_call_ = false;  ///< refusing a block is safe only under lua_pcall (else Lua panics)
  std::atomic<bool> time_up_{false};
  std::atomic<bool> memory_exceeded_{false};
  std::mutex running_mutex_;
  std::string running_;
  std::mutex watch_mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread watchdog_;
};

}  // namespace lunaster::lua
