#pragma once
/// Logging sink injected into engine code (the engine never prints directly).
#include <iostream>
#include <string>

namespace lunaster {

/// Verbosity levels: 0 quiet (errors and TEST_RESU lines only), 1 normal, 2 debug.
class Log {
 public:
  explicit Log(std::ostream& out = std::cout, int verbosity = 1) : out_(&out), verbosity_(verbosity) {}
  void info(const std::string& line) const { if (verbosity_ >= 1) *out_ << line << '\n'; }
  void debug(const std::string& line) const { if (verbosity_ >= 2) *out_ << line << '\n'; }
  /// Warnings are always shown, prefixed "<A> " as code_aster's alarms.
  void warning(const std::string& line) const { *out_ << "<A> " << line << '\n'; ++n_warnings_; }
  /// Always printed (TEST_RESU lines, summaries).
  void always(const std::string& line) const { *out_ << line << '\n'; }
  int verbosity() const { return verbosity_; }
  void set_verbosity(int v) { verbosity_ = v; }
  int n_warnings() const { return n_warnings_; }
  std::ostream& stream() const { return *out_; }

 private:
  std::ostream* out_;
  int verbosity_;
  mutable int n_warnings_ = 0;
};

}  // namespace lunaster
