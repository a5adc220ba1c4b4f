/// .comm -> Lua: a Python tokenizer that keeps every byte's position, a statement pass that
/// decides what is translated and what is refused, and a token rewrite that keeps the
/// layout (the newline count of every token is preserved, so the lines stay aligned).
#include "lua/comm_convert.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <utility>

#include "catalog/args.hpp"
#include "catalog/lookup.hpp"
#include "catalog/spec.hpp"

namespace lunaster::lua {

namespace {

constexpr const char* kMarker = "--[lunaster convert: finish by hand] ";

enum class Kind { Name, Number, String, Op, Comment, Newline, NL, Continuation, Bad };

struct Token {
  Kind kind;
  std::size_t begin = 0, end = 0;  ///< byte range in the (normalised) source
  int line = 1, end_line = 1;      ///< 1-based lines of the first and last byte
  int column = 0;                  ///< column of the first byte (tabs to multiples of 8)
  std::string text;                ///< source text
  // strings
  std::string prefix;              ///< lower-cased prefix letters (r, b, u, f, rb ...)
  char quote = 0;
  bool triple = false;
  bool unterminated = false;
  int match = -1;                  ///< for brackets: index of the matching bracket
};

bool is_ident_start(unsigned char c) { return std::isalpha(c) || c == '_' || c >= 0x80; }
bool is_ident_char(unsigned char c) { return std::isalnum(c) || c == '_' || c >= 0x80; }

bool is_upper_name(const std::string& s) {
  if (s.empty() || !(std::isupper(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (unsigned char c : s)
    if (!(std::isupper(c) || std::isdigit(c) || c == '_')) return false;
  return true;
}

const std::set<std::string>& python_keywords() {
  static const std::set<std::string> k = {
      "False", "None",   "True",     "and",   "as",   "assert", "async",  "await",  "break",
      "class", "continue", "def",    "del",   "elif", "else",   "except", "finally", "for",
      "from",  "global", "if",       "import", "in",  "is",     "lambda", "nonlocal", "not",
      "or",    "pass",   "raise",    "return", "try", "while",  "with",   "yield"};
  return k;
}

/// Python keywords and Lua reserved words all start with a lower-case letter, except True, False
/// and None: most .comm names (upper case) skip the set lookups.
bool maybe_keyword(const std::string& s) {
  return !s.empty() && (std::islower(static_cast<unsigned char>(s[0])) || s == "True" || s == "False" || s == "None");
}
bool is_python_keyword(const std::string& s);
bool is_lua_only_reserved(const std::string& s);

const std::set<std::string>& lua_only_reserved() {
  static const std::set<std::string> k = {"do",  "elseif", "end",  "false", "function", "goto",
                                          "local", "nil",  "repeat", "then", "true",   "until"};
  return k;
}

bool is_python_keyword(const std::string& s) { return maybe_keyword(s) && python_keywords().count(s); }
bool is_lua_only_reserved(const std::string& s) { return maybe_keyword(s) && lua_only_reserved().count(s); }

/// Pieces of a Python string literal after the quote: its value cut at each source newline.
struct StringValue {
  std::vector<std::string> segments{std::string()};
  bool escapes = false;   ///< a backslash was decoded (the body is not the value)
  bool named_escape = false;
};

void append_utf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) out += static_cast<char>(cp);
  else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    if (cp > 0x10FFFF) cp = 0xFFFD;
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

StringValue decode_string(std::string_view body, bool raw, bool bytes) {
  StringValue v;
  auto put = [&](char c) { v.segments.back() += c; };
  std::size_t i = 0;
  const std::size_t n = body.size();
  while (i < n) {
    char c = body[i];
    if (c == '\n') {
      put('\n');
      v.segments.emplace_back();
      ++i;
      continue;
    }
    if (c != '\\' || i + 1 >= n) {
      put(c);
      ++i;
      continue;
    }
    char d = body[i + 1];
    if (raw) {  // the backslash stays, and so does what follows it
      put('\\');
      ++i;
      continue;
    }
    v.escapes = true;
    i += 2;
    switch (d) {
      case '\n': v.segments.emplace_back(); break;  // line continuation inside the string
      case '\r':
        if (i < n && body[i] == '\n') ++i;
        v.segments.emplace_back();
        break;
      case '\\': case '\'': case '"': put(d); break;
      case 'a': put('\a'); break;
      case 'b': put('\b'); break;
      case 'f': put('\f'); break;
      case 'n': put('\n'); break;
      case 'r': put('\r'); break;
      case 't': put('\t'); break;
      case 'v': put('\v'); break;
      case 'x': {
        int h1 = i < n ? hex_digit(body[i]) : -1, h2 = i + 1 < n ? hex_digit(body[i + 1]) : -1;
        if (h1 < 0 || h2 < 0) {
          put('\\');
          put('x');
          break;
        }
        i += 2;
        std::uint32_t cp = static_cast<std::uint32_t>(h1 * 16 + h2);
        if (bytes) put(static_cast<char>(cp));
        else append_utf8(v.segments.back(), cp);
        break;
      }
      case 'u': case 'U': {
        std::size_t len = d == 'u' ? 4 : 8;
        std::uint32_t cp = 0;
        std::size_t k = 0;
        while (!bytes && k < len && i + k < n && hex_digit(body[i + k]) >= 0) cp = cp * 16 + hex_digit(body[i + k++]);
        if (bytes || k < len) {
          put('\\');
          put(d);
          break;
        }
        i += len;
        append_utf8(v.segments.back(), cp);
        break;
      }
      case 'N':
        if (bytes) {
          put('\\');
          put('N');
        } else v.named_escape = true;
        break;
      default:
        if (d >= '0' && d <= '7') {
          std::uint32_t cp = static_cast<std::uint32_t>(d - '0');
          for (int k = 0; k < 2 && i < n && body[i] >= '0' && body[i] <= '7'; ++k) cp = cp * 8 + (body[i++] - '0');
          if (bytes) put(static_cast<char>(cp & 0xFF));
          else append_utf8(v.segments.back(), cp);
        } else {  // Python keeps unknown escapes as they are
          put('\\');
          put(d);
        }
    }
  }
  return v;
}

/// A Lua quoted string holding `value`.
std::string lua_quoted(const std::string& value, char quote) {
  std::string out(1, quote);
  for (std::size_t i = 0; i < value.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(value[i]);
    switch (c) {
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\a': out += "\\a"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\v': out += "\\v"; break;
      default:
        if (c == static_cast<unsigned char>(quote)) {
          out += '\\';
          out += quote;
        } else if (c < 0x20 || c == 0x7F) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\%03u", static_cast<unsigned>(c));
          out += buf;
        } else out += static_cast<char>(c);
    }
  }
  out += quote;
  return out;
}

/// The Lua text of a Python string token (same number of newlines as the token).
std::string lua_string(const Token& t, std::string_view source) {
  const bool raw = t.prefix.find('r') != std::string::npos;
  const bool bytes = t.prefix.find('b') != std::string::npos;
  const std::size_t open = t.prefix.size() + (t.triple ? 3 : 1);
  const std::size_t close = t.triple ? 3 : 1;
  std::string_view body = source.substr(t.begin + open, t.end - t.begin - open - close);
  StringValue v = decode_string(body, raw, bytes);
  if (v.segments.size() == 1) return lua_quoted(v.segments[0], t.quote);
  if (t.triple && (raw || body.find('\\') == std::string_view::npos)) {
    // A long bracket holds the body as it is; Lua drops a newline right after the opening
    // bracket, so a leading newline is given as its own piece.
    std::string level;
    while (body.find("]" + level + "]") != std::string_view::npos) level += '=';
    std::string out;
    std::string_view rest = body;
    if (!rest.empty() && rest[0] == '\n') out = "'\\n' .. ";
    out += "[" + level + "[";
    out += rest;
    out += "]" + level + "]";
    return out;
  }
  std::string out;
  for (std::size_t k = 0; k < v.segments.size(); ++k) {
    if (k) out += " ..\n";
    out += lua_quoted(v.segments[k], t.quote);
  }
  return out;
}

/// Python number literal -> Lua numeral ("" if not representable: complex).
std::string lua_number(std::string text) {
  text.erase(std::remove(text.begin(), text.end(), '_'), text.end());
  if (!text.empty() && (text.back() == 'j' || text.back() == 'J')) return {};
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'o' || text[1] == 'O' || text[1] == 'b' || text[1] == 'B')) {
    const int base = (text[1] == 'o' || text[1] == 'O') ? 8 : 2;
    unsigned long long value = 0;
    bool overflow = false;
    for (std::size_t i = 2; i < text.size(); ++i) {
      unsigned long long next = value * base + static_cast<unsigned long long>(text[i] - '0');
      if (next / base != value) overflow = true;
      value = next;
    }
    if (overflow || value > 0x7FFFFFFFFFFFFFFFULL) return {};
    return std::to_string(value);
  }
  return text;
}

struct Tokenized {
  std::string source;  ///< the text with lone carriage returns made blanks
  std::vector<Token> tokens;
  std::vector<CommIssue> issues;  ///< lexical problems
  std::vector<int> bad_tokens;    ///< token indices carrying a lexical problem (their statement is refused)
  int n_lines = 1;
};

Tokenized tokenize(std::string_view text) {
  Tokenized r;
  r.source.assign(text.begin(), text.end());
  for (std::size_t i = 0; i < r.source.size(); ++i)
    if (r.source[i] == '\r' && (i + 1 >= r.source.size() || r.source[i + 1] != '\n')) r.source[i] = ' ';
  const std::string& s = r.source;
  const std::size_t n = s.size();
  std::size_t i = 0;
  int line = 1;
  std::size_t line_start = 0;
  int depth = 0;
  bool content = false;  // significant token since the last Newline
  std::size_t col_pos = 0;  // column_of walks each line once
  int col_value = 0;
  auto column_of = [&](std::size_t pos) {
    if (col_pos < line_start || col_pos > pos) {
      col_pos = line_start;
      col_value = 0;
    }
    for (; col_pos < pos; ++col_pos) col_value = s[col_pos] == '\t' ? (col_value / 8 + 1) * 8 : col_value + 1;
    return col_value;
  };
  auto push = [&](Kind kind, std::size_t b, std::size_t e) -> Token& {
    Token t;
    t.kind = kind;
    t.begin = b;
    t.end = e;
    t.line = line;
    t.column = column_of(b);
    t.text = s.substr(b, e - b);
    t.end_line = line + static_cast<int>(std::count(t.text.begin(), t.text.end(), '\n'));
    r.tokens.push_back(std::move(t));
    return r.tokens.back();
  };
  auto bad = [&](std::string what, std::string hint) {
    r.bad_tokens.push_back(static_cast<int>(r.tokens.size()) - 1);
    r.issues.push_back({r.tokens.back().line, std::move(what), std::move(hint)});
  };
  auto advance_lines = [&](const Token& t) {
    for (std::size_t k = t.begin; k < t.end; ++k)
      if (s[k] == '\n') {
        ++line;
        line_start = k + 1;
      }
  };
  while (i < n) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c == ' ' || c == '\t' || c == '\f' || c == '\r' || c == '\v') {
      ++i;
      continue;
    }
    if (c == '\n') {
      Token& t = push(depth == 0 && content ? Kind::Newline : Kind::NL, i, i + 1);
      if (t.kind == Kind::Newline) content = false;
      advance_lines(t);
      ++i;
      continue;
    }
    if (c == '#') {
      std::size_t e = s.find('\n', i);
      if (e == std::string::npos) e = n;
      push(Kind::Comment, i, e);
      i = e;
      continue;
    }
    if (c == '\\') {
      std::size_t e = i + 1;
      while (e < n && (s[e] == ' ' || s[e] == '\t' || s[e] == '\r')) ++e;
      if (e < n && s[e] == '\n') {
        Token& t = push(Kind::Continuation, i, e + 1);
        advance_lines(t);
        i = e + 1;
      } else {
        push(Kind::Bad, i, i + 1);
        bad("unexpected '\\' (a backslash continues a line only at its end)", "remove it");
        content = true;
        ++i;
      }
      continue;
    }
    content = true;
    // strings, with their prefix letters
    std::size_t p = i;
    while (p < n && p - i < 3 && std::isalpha(static_cast<unsigned char>(s[p]))) ++p;
    std::string prefix;
    for (std::size_t k = i; k < p; ++k) prefix += static_cast<char>(std::tolower(static_cast<unsigned char>(s[k])));
    static const std::set<std::string> prefixes = {"", "r", "u", "f", "b", "br", "rb", "fr", "rf"};
    if (p < n && (s[p] == '\'' || s[p] == '"') && prefixes.count(prefix) &&
        (p == i || !(i > 0 && is_ident_char(static_cast<unsigned char>(s[i - 1]))))) {
      const char q = s[p];
      const bool triple = p + 2 < n && s[p + 1] == q && s[p + 2] == q;
      std::size_t k = p + (triple ? 3 : 1);
      bool closed = false;
      while (k < n) {
        if (s[k] == '\\' && k + 1 < n) {
          k += 2;
          continue;
        }
        if (triple) {
          if (s[k] == q && k + 2 < n && s[k + 1] == q && s[k + 2] == q) {
            k += 3;
            closed = true;
            break;
          }
        } else {
          if (s[k] == '\n') break;
          if (s[k] == q) {
            ++k;
            closed = true;
            break;
          }
        }
        ++k;
      }
      if (!closed && triple) k = n;
      Token& t = push(Kind::String, i, k);
      t.prefix = prefix;
      t.quote = q;
      t.triple = triple;
      t.unterminated = !closed;
      advance_lines(t);
      if (!closed)
        bad(triple ? "unterminated triple-quoted string" : "unterminated string", "close the string with its quote");
      i = k;
      continue;
    }
    if (std::isdigit(c) || (c == '.' && i + 1 < n && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      std::size_t k = i;
      if (c == '0' && k + 1 < n && std::strchr("xXoObB", s[k + 1]) && s[k + 1] != '\0') {
        k += 2;
        while (k < n && (std::isxdigit(static_cast<unsigned char>(s[k])) || s[k] == '_')) ++k;
      } else {
        while (k < n && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '_')) ++k;
        if (k < n && s[k] == '.') {
          ++k;
          while (k < n && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '_')) ++k;
        }
        if (k < n && (s[k] == 'e' || s[k] == 'E')) {
          std::size_t e = k + 1;
          if (e < n && (s[e] == '+' || s[e] == '-')) ++e;
          if (e < n && std::isdigit(static_cast<unsigned char>(s[e]))) {
            k = e;
            while (k < n && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '_')) ++k;
          }
        }
        if (k < n && (s[k] == 'j' || s[k] == 'J')) ++k;
      }
      push(Kind::Number, i, k);
      i = k;
      continue;
    }
    if (is_ident_start(c)) {
      std::size_t k = i;
      while (k < n && is_ident_char(static_cast<unsigned char>(s[k]))) ++k;
      push(Kind::Name, i, k);
      i = k;
      continue;
    }
    static const char* const ops[] = {"**=", "//=", ">>=", "<<=", "...", "!=", "==", "<=", ">=", "**", "//", "<<",
                                      ">>",  "->",  ":=",  "+=",  "-=",  "*=", "/=", "%=", "&=", "|=", "^=", "@="};
    std::size_t len = 0;
    if (i + 1 < n && std::strchr("*/<>.!=-:+%&|^@", s[i + 1]) && s[i + 1] != '\0')
      for (const char* op : ops) {
        const std::size_t l = op[2] ? 3 : 2;
        if (i + l <= n && s[i] == op[0] && s[i + 1] == op[1] && (l == 2 || s[i + 2] == op[2])) {
          len = l;
          break;
        }
      }
    if (!len && std::strchr("+-*/%<>=()[]{},:;.@&|^~", c) && c != '\0') len = 1;
    if (!len) {
      std::size_t k = i + 1;
      push(Kind::Bad, i, k);
      bad("unexpected character '" + s.substr(i, 1) + "'", "remove it");
      i = k;
      continue;
    }
    push(Kind::Op, i, i + len);
    if (len == 1 && std::strchr("([{", c)) ++depth;
    if (len == 1 && std::strchr(")]}", c) && depth > 0) --depth;
    i += len;
  }
  r.n_lines = line;
  // brackets
  std::vector<int> stack;
  for (int k = 0; k < static_cast<int>(r.tokens.size()); ++k) {
    Token& t = r.tokens[k];
    if (t.kind != Kind::Op || t.text.size() != 1) continue;
    const char c = t.text[0];
    if (c == '(' || c == '[' || c == '{') stack.push_back(k);
    else if (c == ')' || c == ']' || c == '}') {
      const char want = c == ')' ? '(' : c == ']' ? '[' : '{';
      if (!stack.empty() && r.tokens[stack.back()].text[0] == want) {
        t.match = stack.back();
        r.tokens[stack.back()].match = k;
        stack.pop_back();
      } else {
        r.bad_tokens.push_back(k);
        r.issues.push_back({t.line, "unmatched '" + t.text + "'", "remove it or open the bracket it closes"});
        if (!stack.empty()) stack.pop_back();
      }
    }
  }
  for (int k : stack) {
    r.bad_tokens.push_back(k);
    r.issues.push_back({r.tokens[k].line, "unclosed '" + r.tokens[k].text + "'",
                        "close it: the rest of the file is one statement until then and was not translated"});
  }
  return r;
}

bool significant(const Token& t) {
  return t.kind != Kind::Comment && t.kind != Kind::NL && t.kind != Kind::Newline && t.kind != Kind::Continuation;
}
bool is_op(const Token& t, const char* op) { return t.kind == Kind::Op && t.text == op; }
bool is_name(const Token& t, const char* name) { return t.kind == Kind::Name && t.text == name; }

/// One logical line: significant token indices, in order.
struct Statement {
  std::vector<int> toks;
  int first_line = 0, last_line = 0, indent = 0;
  bool refused = false;
  std::vector<CommIssue> reasons;
};

std::string hint_for_function(const std::string& name) {
  static const std::set<std::string> math = {"sqrt", "sin", "cos",  "tan",  "exp",  "log",  "atan", "asin",
                                             "acos", "floor", "ceil", "pow", "atan2", "fabs", "log10"};
  if (math.count(name))
    return "compute the value and write it, or finish in Lua (math." + std::string(name == "fabs" ? "abs" : name) + ")";
  if (name == "abs" || name == "min" || name == "max")
    return "compute the value and write it, or finish in Lua (math." + name + ")";
  if (name == "range") return "write the values out, or finish with a Lua loop (for i = a, b do ... end)";
  if (name == "print") return "drop it, or finish in Lua (print)";
  if (name == "float" || name == "int" || name == "str")
    return "write the value, or finish in Lua (tonumber, tostring, math.floor)";
  if (name == "len") return "write the count, or finish in Lua (#t)";
  return "compute the value and write it, or finish in Lua";
}

/// The translation of a whole file: tokens with their Lua text, and the statements.
struct Analysis {
  Tokenized tz;
  std::vector<std::string> out;  ///< per token
  std::vector<std::string> pre, post;  ///< per token: text written before / after its translation
  std::set<std::string> functions;     ///< names of the file's `def`s (called as functions, not commands)
  std::vector<Statement> statements;
  std::vector<CommIssue> refused;
  std::vector<char> refused_line;  ///< per line (1-based)
};

class Translator {
 public:
  explicit Translator(Analysis& a) : a_(a), t_(a.tz.tokens) {}

  void run() {
    split_statements();
    a_.out.resize(t_.size());
    a_.pre.assign(t_.size(), std::string());
    a_.post.assign(t_.size(), std::string());
    skip_.assign(t_.size(), 0);
    for (std::size_t k = 0; k < t_.size(); ++k) a_.out[k] = t_[k].text;
    prepass();
    translate_range(0, a_.statements.size(), Context{});
    a_.functions = functions_;
    // issues: lexical first-class, then statements, in line order
    a_.refused_line.assign(static_cast<std::size_t>(a_.tz.n_lines) + 2, 0);
    for (const auto& st : a_.statements) {
      if (!st.refused) continue;
      for (int l = st.first_line; l <= st.last_line; ++l) a_.refused_line[l] = 1;
      for (const auto& r : st.reasons) a_.refused.push_back(r);
    }
    std::stable_sort(a_.refused.begin(), a_.refused.end(),
                     [](const CommIssue& x, const CommIssue& y) { return x.line < y.line; });
  }

 private:
  Analysis& a_;
  std::vector<Token>& t_;
  /// Where a statement sits: inside a `def` body (return, local names) and inside a loop (break).
  struct Context {
    bool in_def = false, in_loop = false;
  };
  std::vector<char> skip_;  ///< per token: already written by a construct's rewrite, not translated again
  std::set<std::string> assigned_;    ///< names the file binds (assignment, loop, def parameters)
  std::set<std::string> functions_;   ///< names of its defs, and of its function concepts (FORMULE ...)
  /// math's names a deck uses bare: code_aster runs command files with math's functions at hand,
  /// so all of them unless the deck binds the name itself
  std::set<std::string> math_names_ = math_module_names();
  bool math_local_ = false;  ///< the deck imports math: `local math = py.math` is written at its import
  std::set<int> stringy_end_;         ///< tokens ending an expression that gives a text ('%' or .format)

  static const std::set<std::string>& math_module_names() {
    static const std::set<std::string> k = {
        "pi",   "e",     "tau",   "inf",  "nan",  "sqrt",  "exp",   "log",     "log10",    "log2",   "pow",
        "sin",  "cos",   "tan",   "asin", "acos", "atan",  "atan2", "sinh",    "cosh",     "tanh",   "asinh",
        "acosh", "atanh", "fabs", "floor", "ceil", "trunc", "fmod", "hypot",   "degrees",  "radians", "copysign",
        "isnan", "isinf", "isfinite", "factorial"};
    return k;
  }
  /// Python built-ins the `py` library provides (called as py.NAME).
  static const std::set<std::string>& builtin_names() {
    static const std::set<std::string> k = {"abs", "min",   "max",   "len",   "range", "int",    "float", "str",
                                            "round", "sum", "list",  "tuple", "pow",   "bool",   "sorted"};
    return k;
  }
  bool shadowed(const std::string& name) const { return assigned_.count(name) || functions_.count(name); }
  /// A name a translated call may name: a def of the file, a math function imported, a built-in, print.
  bool callable_name(const std::string& name) const {
    return functions_.count(name) || (math_names_.count(name) && !shadowed(name)) ||
           (builtin_names().count(name) && !shadowed(name)) || name == "print";
  }

  /// Names bound anywhere in the file, the defs, and what `from math import` brings.
  void prepass() {
    for (const Statement& st : a_.statements) {
      const auto& tk = st.toks;
      const Token& f = t_[tk.front()];
      if (is_name(f, "def") && tk.size() > 2 && t_[tk[1]].kind == Kind::Name) {
        functions_.insert(t_[tk[1]].text);
        for (std::size_t p = 3; p < tk.size(); ++p)
          if (t_[tk[p]].kind == Kind::Name && (is_op(t_[tk[p - 1]], "(") || is_op(t_[tk[p - 1]], ",")))
            assigned_.insert(t_[tk[p]].text);
      } else if (is_name(f, "for")) {
        for (std::size_t p = 1; p < tk.size() && !is_name(t_[tk[p]], "in"); ++p)
          if (t_[tk[p]].kind == Kind::Name) assigned_.insert(t_[tk[p]].text);
      } else if ((is_name(f, "from") || is_name(f, "import")) && tk.size() >= 2 && is_name(t_[tk[1]], "math")) {
        math_local_ = true;
      } else {  // A = ..., A, B = ..., each part of A = 1; B = 2
        std::size_t start = 0;
        bool seen = false;
        for (std::size_t p = 0; p < tk.size(); ++p) {
          const Token& t = t_[tk[p]];
          if (is_op(t, ";")) {
            start = p + 1;
            seen = false;
          } else if (t.kind == Kind::Op && t.match > tk[p] && std::strchr("([{", t.text[0])) {
            seen = true;
            p = pos_of(st, t.match);
          } else if (is_op(t, "=") && !seen) {
            for (std::size_t q = start; q < p; ++q)
              if (t_[tk[q]].kind == Kind::Name) assigned_.insert(t_[tk[q]].text);
            seen = true;
            // F = FORMULE(...): F(x) is then a call of the function, as in code_aster's Python
            static const std::set<std::string> makers = {"FORMULE", "DEFI_FONCTION", "DEFI_CONSTANTE", "CALC_FONC_INTERP"};
            if (p == start + 1 && p + 2 < tk.size() && makers.count(t_[tk[p + 1]].text) && is_op(t_[tk[p + 2]], "("))
              functions_.insert(t_[tk[start]].text);
          }
        }
      }
    }
  }

  void translate_range(std::size_t from, std::size_t to, Context context) {
    std::size_t k = from;
    while (k < to) {
      if (is_block_header(a_.statements[k])) {
        k = translate_block(k, to, context);
        continue;
      }
      translate(a_.statements[k], context);
      ++k;
    }
  }

  /// for / while / if-elif-else / def blocks: the header in Lua, the body translated, `end` after its last token.
  /// Any statement of the block refused refuses the whole block. Returns the index past the block.
  std::size_t translate_block(std::size_t k, std::size_t to, Context context) {
    Statement& h = a_.statements[k];
    const Token& f = t_[h.toks.front()];
    const std::size_t end = std::min(block_end(k), to);
    const std::string word = f.kind == Kind::Name ? f.text : std::string();
    if (word != "for" && word != "if" && word != "while" && word != "def") {
      refuse_block(k, end);
      return end;
    }
    std::vector<std::size_t> heads = {k}, ends = {end};
    if (word == "if") {
      while (ends.back() < to) {
        const Statement& s = a_.statements[ends.back()];
        const Token& g = t_[s.toks.front()];
        if (s.indent != h.indent || !(is_name(g, "elif") || is_name(g, "else"))) break;
        heads.push_back(ends.back());
        ends.push_back(std::min(block_end(ends.back()), to));
        if (g.text == "else") break;
      }
    }
    for (std::size_t i = 0; i < heads.size(); ++i) {
      Statement& hs = a_.statements[heads[i]];
      const Token& g = t_[hs.toks.front()];
      add_lexical(hs);
      Context inner = context;
      if (word == "for" || word == "while") inner.in_loop = true;
      if (word == "def") inner = Context{true, false};
      const std::size_t inline_colon = ends[i] == heads[i] + 1 && word != "def" ? top_level_colon(hs) : 0;
      if (hs.reasons.empty() && inline_colon) {
        // `if c: return x` on one line: the header, then its one-statement body, `end` after it
        Statement head = hs, body = hs;
        head.toks.resize(inline_colon + 1);
        body.toks.erase(body.toks.begin(), body.toks.begin() + static_cast<std::ptrdiff_t>(inline_colon) + 1);
        head.reasons.clear();
        body.reasons.clear();
        translate_header(head, heads[i], ends[i]);
        if (is_block_header(body))
          body.reasons.push_back({t_[body.toks.front()].line, "a block inside a one-line '" + g.text + "'",
                                  "put the body on the lines below it, indented"});
        else
          translate(body, inner);
        hs.reasons = head.reasons;
        hs.reasons.insert(hs.reasons.end(), body.reasons.begin(), body.reasons.end());
      } else if (hs.reasons.empty()) {
        if (!is_op(t_[hs.toks.back()], ":"))
          hs.reasons.push_back({g.line, "'" + g.text + "' with its body on the same line",
                                "put the body on the lines below it, indented"});
        else if (ends[i] == heads[i] + 1)
          hs.reasons.push_back({g.line, "'" + g.text + "' without a body", "write the body, indented, below it"});
        else
          translate_header(hs, heads[i], ends[i]);
      }
      if (!hs.reasons.empty()) hs.refused = true;
      translate_range(heads[i] + 1, ends[i], inner);
    }
    const std::size_t last = ends.back();
    a_.post[a_.statements[last - 1].toks.back()] += " end";
    bool refused = false;
    for (std::size_t j = k; j < last; ++j) refused = refused || a_.statements[j].refused;
    if (refused)
      for (std::size_t j = k; j < last; ++j) a_.statements[j].refused = true;
    return last;
  }

  /// Position of the ':' ending a header followed by its body on the same line (0 if none).
  std::size_t top_level_colon(const Statement& st) const {
    for (std::size_t p = 1; p + 1 < st.toks.size(); ++p) {
      const Token& t = t_[st.toks[p]];
      if (t.kind == Kind::Op && t.match > st.toks[p] && std::strchr("([{", t.text[0])) p = pos_of(st, t.match);
      else if (is_name(t, "lambda")) return 0;
      else if (is_op(t, ":")) return p;
    }
    return 0;
  }

  auto refuser(Statement& st) {
    return [this, &st](const Token& t, std::string what, std::string hint) {
      for (const auto& r : st.reasons)
        if (r.line == t.line && r.what == what) return;
      st.reasons.push_back({t.line, std::move(what), std::move(hint)});
    };
  }

  /// The header of a block (its last token is ':'), statement `head` whose body ends before `end`.
  void translate_header(Statement& st, std::size_t head, std::size_t end) {
    auto refuse = refuser(st);
    const std::size_t n = st.toks.size();
    const int word = st.toks.front(), colon = st.toks.back();
    const std::string& w = t_[word].text;
    if (w == "else") {
      a_.out[colon] = "";
      if (n != 2) refuse(t_[word], "'else' followed by something before ':'", "write else: alone");
      return;
    }
    if (w == "if" || w == "elif" || w == "while") {
      if (n < 3) {
        refuse(t_[word], "'" + w + "' without a condition", "write the condition before ':'");
        return;
      }
      if (w == "elif") a_.out[word] = "elseif";
      a_.out[colon] = w == "while" ? " do" : " then";
      translate_tokens(st, 1, n - 2, refuse);
      return;
    }
    if (w == "for") {
      if (n < 5 || t_[st.toks[1]].kind != Kind::Name || !is_name(t_[st.toks[2]], "in")) {
        refuse(t_[word], "'for' loop over several names", "loop over one name: for x in values:");
        return;
      }
      skip_[st.toks[2]] = 1;
      translate_tokens(st, 1, n - 2, refuse);
      a_.out[colon] = " do";
      const std::size_t a = 3, b = n - 2;  // the iterable
      const Token& r = t_[st.toks[a]];
      if (is_name(r, "range") && !shadowed("range") && a + 1 < b && is_op(t_[st.toks[a + 1]], "(") &&
          t_[st.toks[a + 1]].match == st.toks[b]) {
        const auto args = arguments(st, a + 1, b);
        std::string close = ") - 1";
        bool numeric = !args.empty() && args.size() <= 3;
        if (args.size() == 3) {  // a literal step: the bound is inclusive in Lua
          const bool negative = is_op(t_[st.toks[args[2].first]], "-");
          const std::size_t lit = args[2].first + (negative ? 1 : 0);
          const std::string& digits = t_[st.toks[lit]].text;
          numeric = lit == args[2].second && t_[st.toks[lit]].kind == Kind::Number &&
                    digits.find_first_not_of("0123456789") == std::string::npos && digits.find_first_not_of('0') != std::string::npos;
          if (negative) close = ") + 1";
        }
        if (numeric) {
          const auto& stop = args.size() == 1 ? args[0] : args[1];
          a_.out[st.toks[2]] = "=";
          a_.pre[st.toks[a]] = "";
          a_.out[st.toks[a]] = args.size() == 1 ? "0, " : "";
          a_.out[st.toks[a + 1]] = "";
          a_.pre[st.toks[stop.first]] = "(" + a_.pre[st.toks[stop.first]];
          a_.post[st.toks[stop.second]] += close;
          a_.out[st.toks[b]] = "";
          return;
        }
      }
      a_.pre[st.toks[1]] = "_, " + a_.pre[st.toks[1]];
      a_.pre[st.toks[a]] = "ipairs(" + a_.pre[st.toks[a]];
      a_.post[st.toks[b]] += ")";
      return;
    }
    // def NAME(a, b): -> function NAME(a, b) local <the names its body assigns>
    if (n < 5 || t_[st.toks[1]].kind != Kind::Name || !is_op(t_[st.toks[2]], "(") ||
        t_[st.toks[2]].match != st.toks[n - 2]) {
      refuse(t_[word], "function definition in another form than 'def name(a, b):'", "write it as a Lua function by hand");
      return;
    }
    std::set<std::string> parameters;
    for (const auto& [x, y] : arguments(st, 2, n - 2)) {
      if (x != y || t_[st.toks[x]].kind != Kind::Name) {
        refuse(t_[st.toks[x]], "parameter with a default value or a '*' form in 'def " + t_[st.toks[1]].text + "'",
               "give every parameter at each call, or finish by hand in Lua");
        return;
      }
      parameters.insert(t_[st.toks[x]].text);
    }
    translate_tokens(st, 1, n - 2, refuse);
    a_.out[word] = "function";
    a_.pre[st.toks[1]].clear();
    std::set<std::string> globals;
    std::vector<std::string> locals;
    for (std::size_t j = head + 1; j < end; ++j) {
      const auto& tk = a_.statements[j].toks;
      if (is_name(t_[tk.front()], "global"))
        for (int q : tk)
          if (t_[q].kind == Kind::Name) globals.insert(t_[q].text);
    }
    for (std::size_t j = head + 1; j < end; ++j) {
      const auto& tk = a_.statements[j].toks;
      if (is_block_header(a_.statements[j])) continue;
      for (std::size_t p = 0; p < tk.size(); ++p) {
        const Token& t = t_[tk[p]];
        if (t.kind == Kind::Op && t.match > tk[p] && std::strchr("([{", t.text[0])) break;
        if (!is_op(t, "=")) continue;
        for (std::size_t q = 0; q < p; ++q) {
          const std::string& name = t_[tk[q]].text;
          if (t_[tk[q]].kind == Kind::Name && !parameters.count(name) && !globals.count(name) &&
              std::find(locals.begin(), locals.end(), name) == locals.end())
            locals.push_back(name);
        }
        break;
      }
    }
    std::string declared;
    for (const auto& name : locals) declared += (declared.empty() ? " local " : ", ") + name;
    a_.out[colon] = declared;
  }

  void split_statements() {
    Statement cur;
    auto close = [&](int last_tok) {
      if (cur.toks.empty()) return;
      cur.first_line = t_[cur.toks.front()].line;
      cur.last_line = t_[last_tok].end_line;
      cur.indent = t_[cur.toks.front()].column;
      a_.statements.push_back(std::move(cur));
      cur = Statement();
    };
    int last = -1;
    for (int k = 0; k < static_cast<int>(t_.size()); ++k) {
      const Token& t = t_[k];
      if (t.kind == Kind::Newline) {
        close(last);
        continue;
      }
      if (significant(t)) {
        cur.toks.push_back(k);
        last = k;
      } else if (t.kind == Kind::Comment && !cur.toks.empty()) last = k;
    }
    close(last);
  }

  bool is_block_header(const Statement& st) const {
    const Token& f = t_[st.toks.front()];
    static const std::set<std::string> heads = {"for", "while", "if",   "elif", "else", "try",
                                                "except", "finally", "with", "def", "class", "async"};
    return (f.kind == Kind::Name && heads.count(f.text)) || is_op(f, "@");
  }

  /// Index past the last statement of the block headed by statement k (k + 1 if no block).
  std::size_t block_end(std::size_t k) const {
    if (!is_block_header(a_.statements[k])) return k + 1;
    const int indent = a_.statements[k].indent;
    std::size_t e = k + 1;
    while (e < a_.statements.size() && a_.statements[e].indent > indent) ++e;
    return e;
  }

  void refuse_block(std::size_t k, std::size_t end) {
    Statement& h = a_.statements[k];
    const Token& f = t_[h.toks.front()];
    std::string what, hint;
    const std::string next = h.toks.size() > 1 ? t_[h.toks[1]].text : "";
    if (f.text == "for" || f.text == "while") {
      what = "'" + f.text + "' loop";
      hint = "write the repeated commands out, or finish with a Lua loop (for i = 1, n do ... end)";
    } else if (f.text == "if" || f.text == "elif" || f.text == "else") {
      what = "'" + f.text + "' block";
      hint = "keep the branch you need, or finish in Lua (if ... then ... end)";
    } else if (f.text == "try" || f.text == "except" || f.text == "finally") {
      what = "'" + f.text + "' block";
      hint = "keep the commands of the body: lunaster stops with a clear error instead of raising exceptions";
    } else if (f.text == "with") {
      what = "'with' block";
      hint = "keep the commands of the body, or finish in Lua";
    } else if (f.text == "def") {
      what = "function definition 'def " + next + "'";
      hint = "write it as a Lua function (function " + next + "(...) ... end), or write its commands out";
    } else if (f.text == "class") {
      what = "class definition 'class " + next + "'";
      hint = "not translatable: finish by hand in Lua";
    } else if (f.text == "@") {
      what = "decorator '@" + next + "'";
      hint = "not translatable: finish by hand in Lua";
    } else {
      what = "'" + f.text + "' statement";
      hint = "not translatable: finish by hand in Lua";
    }
    h.reasons.push_back({f.line, what, hint});
    add_lexical(h);
    for (std::size_t j = k; j < end; ++j) {
      a_.statements[j].refused = true;
      if (j > k) add_lexical(a_.statements[j]);
    }
  }

  /// Lexical problems are reported wherever they are.
  void add_lexical(Statement& st) {
    for (std::size_t idx = 0; idx < a_.tz.bad_tokens.size(); ++idx) {
      int b = a_.tz.bad_tokens[idx];
      if (std::binary_search(st.toks.begin(), st.toks.end(), b)) st.reasons.push_back(a_.tz.issues[idx]);
    }
  }

  /// Previous significant token of the statement before position p (index into st.toks), or nullptr.
  const Token* prev(const Statement& st, std::size_t p) const { return p == 0 ? nullptr : &t_[st.toks[p - 1]]; }
  const Token* next(const Statement& st, std::size_t p) const {
    return p + 1 >= st.toks.size() ? nullptr : &t_[st.toks[p + 1]];
  }
  std::size_t pos_of(const Statement& st, int tok) const {
    return static_cast<std::size_t>(std::lower_bound(st.toks.begin(), st.toks.end(), tok) - st.toks.begin());
  }

  static bool callable_before(const Token* t) {
    if (!t) return false;
    if (t->kind == Kind::Name) return !is_python_keyword(t->text);
    if (t->kind == Kind::String) return true;
    return t->kind == Kind::Op && (t->text == ")" || t->text == "]" || t->text == "}");
  }

  /// Top-level argument ranges [first, last] (positions in st.toks) between the brackets at positions o and c.
  std::vector<std::pair<std::size_t, std::size_t>> arguments(const Statement& st, std::size_t o, std::size_t c) const {
    std::vector<std::pair<std::size_t, std::size_t>> args;
    std::size_t start = o + 1;
    for (std::size_t p = o + 1; p < c; ++p) {
      const Token& t = t_[st.toks[p]];
      if (t.match > st.toks[p] && t.kind == Kind::Op && std::strchr("([{", t.text[0])) {
        p = pos_of(st, t.match);
        continue;
      }
      if (is_op(t, ",")) {
        if (p > start) args.push_back({start, p - 1});
        start = p + 1;
      }
    }
    if (c > start) args.push_back({start, c - 1});
    return args;
  }

  /// code_aster's table cell TAB['PARA', i] (a text, one top-level comma, the row) is the deck
  /// spelling TAB['PARA'][i]: the comma becomes "][". The bracket at position `o` of `st`.
  bool table_cell(const Statement& st, std::size_t o) {
    const std::size_t c = pos_of(st, t_[st.toks[o]].match);
    if (c < o + 4 || t_[st.toks[o + 1]].kind != Kind::String || !is_op(t_[st.toks[o + 2]], ",")) return false;
    for (std::size_t q = o + 3; q < c; ++q) {  // the row: one expression, no second comma
      const Token& u = t_[st.toks[q]];
      if (u.match > st.toks[q] && u.kind == Kind::Op && std::strchr("([{", u.text[0])) {
        q = pos_of(st, u.match);
        continue;
      }
      if (is_op(u, ",")) return false;
    }
    a_.out[st.toks[o + 2]] = "][";
    return true;
  }

  bool has_top_comma(const Statement& st, std::size_t o, std::size_t c) const {
    for (std::size_t p = o + 1; p < c; ++p) {
      const Token& t = t_[st.toks[p]];
      if (t.match > st.toks[p] && t.kind == Kind::Op && std::strchr("([{", t.text[0])) {
        p = pos_of(st, t.match);
        continue;
      }
      if (is_op(t, ",")) return true;
    }
    return false;
  }

  void translate(Statement& st, Context context) {
    std::vector<CommIssue>& why = st.reasons;
    add_lexical(st);
    if (!why.empty()) {  // unterminated or stray: the statement is not read further, one issue says why
      st.refused = true;
      return;
    }
    auto refuse = refuser(st);
    const Token& first = t_[st.toks.front()];
    const std::size_t n = st.toks.size();
    static const std::set<std::string> statement_words = {"import", "from",     "return", "pass",  "del",
                                                          "global", "nonlocal", "raise",  "assert", "yield",
                                                          "break",  "continue"};
    if (first.kind == Kind::Name && statement_words.count(first.text)) {
      const std::string& w = first.text;
      if (w == "import" || w == "from") translate_import(st, refuse);
      else if (w == "return" && context.in_def) translate_tokens(st, 1, n - 1, refuse);
      else if (w == "return") refuse(first, "'return' outside a function", "remove it");
      else if (w == "pass") a_.out[st.toks.front()] = "";
      else if (w == "break" && context.in_loop && n == 1) {
      } else if (w == "global" && context.in_def && st.first_line == st.last_line) {
        a_.out[st.toks.front()] = "-- global";  // Lua's names are global unless declared local
      } else if (w == "continue")
        refuse(first, "'continue' statement", "put the rest of the loop's body under an 'if', or finish by hand in Lua (goto)");
      else
        refuse(first, "'" + w + "' statement", "not translatable: finish by hand in Lua");
      if (!why.empty()) st.refused = true;
      return;
    }
    translate_tokens(st, 0, n - 1, refuse);
    if (std::all_of(st.toks.begin(), st.toks.end(), [&](int k) { return t_[k].kind == Kind::String; })) {
      a_.pre[st.toks.front()] = "local _ = " + a_.pre[st.toks.front()];  // a docstring: Lua has no bare values
    } else {
      check_statement_form(st, refuse);
    }
    if (!why.empty()) st.refused = true;
  }

  /// import math, from math import ..., from code_aster.Commands import ...: the rest is refused.
  template <class Refuse>
  void translate_import(Statement& st, Refuse& refuse) {
    const auto& tk = st.toks;
    const Token& first = t_[tk.front()];
    std::string module;
    for (std::size_t p = 1; p < tk.size() && !is_name(t_[tk[p]], "import") && !is_name(t_[tk[p]], "as"); ++p)
      module += t_[tk[p]].text;
    const bool as = std::any_of(tk.begin(), tk.end(), [&](int k) { return is_name(t_[k], "as"); });
    if (st.first_line == st.last_line && !as) {
      if (first.text == "import" && module == "math" && tk.size() == 2) {
        a_.out[tk[0]] = "local";
        a_.out[tk[1]] = "math = py.math";
        return;
      }
      if (first.text == "from" && module == "math") {
        a_.out[tk[0]] = "local math = py.math -- from";
        return;
      }
      if (first.text == "from" && module == "code_aster.Commands") {  // the commands are lunaster's own
        a_.out[tk[0]] = "-- from";
        return;
      }
    }
    refuse(first, "import of '" + module + "'" + (as ? " under another name" : ""),
           "lunaster translates 'import math' and 'from math import ...' (Lua's math with Python's names); "
           "remove this one or finish by hand");
  }

  /// Translates the tokens at positions [from, to] of `st` (an expression, a simple statement, a header's part).
  template <class Refuse>
  void translate_tokens(Statement& st, std::size_t from, std::size_t to, Refuse& refuse) {
    // Bracket kinds: '(' call of a command, tuple, parenthesised value; '[' list.
    bool comprehension = false, ternary = false;
    for (std::size_t p = from; p <= to && p < st.toks.size(); ++p) {
      const int k = st.toks[p];
      if (skip_[k]) continue;
      const Token& t = t_[k];
      const Token* before = prev(st, p);
      const Token* after = next(st, p);
      switch (t.kind) {
        case Kind::Name: {
          if (t.text == "True") a_.out[k] = "true";
          else if (t.text == "False") a_.out[k] = "false";
          else if (t.text == "None") a_.out[k] = "nil";
          else if (t.text == "and" || t.text == "or" || t.text == "not") {
          } else if (t.text == "lambda") {
            refuse(t, "'lambda'", "write a Lua function by hand (function (x) return ... end)");
          } else if (t.text == "for") {
            if (!comprehension)
              refuse(t, "list comprehension or generator ('for' inside an expression)",
                     "write the values out, or build the table with a Lua loop");
            comprehension = true;
          } else if (t.text == "if" && !comprehension) {
            refuse(t, "conditional expression 'a if c else b'",
                   "compute the value and write it, or finish in Lua (c and a or b)");
            ternary = true;
          } else if ((t.text == "else" && ternary) || ((t.text == "in" || t.text == "if") && comprehension)) {
          } else if (t.text == "in" || t.text == "is") {
            refuse(t, "Python operator '" + t.text + "'", "compute the value and write it, or finish in Lua");
          } else if (t.text == "exec" || t.text == "eval") {
            refuse(t, "'" + t.text + "'", "not translatable: write out the code it runs");
          } else if (is_python_keyword(t.text)) {
            refuse(t, "'" + t.text + "' inside a statement", "not translatable: finish by hand in Lua");
          } else if (is_lua_only_reserved(t.text)) {
            refuse(t, "identifier '" + t.text + "' (a Lua reserved word)",
                   "rename it everywhere in the study (e.g. '" + t.text + "_')");
          } else {
            bool ascii = std::all_of(t.text.begin(), t.text.end(), [](char c) { return (c & 0x80) == 0; });
            if (!ascii) refuse(t, "non-ASCII identifier '" + t.text + "'", "rename it with ASCII letters");
            translate_name(k, before, after);
          }
          break;
        }
        case Kind::Number: {
          std::string lua = lua_number(t.text);
          if (lua.empty()) {
            refuse(t, "number '" + t.text + "'", "not representable in a Lua deck: write a real or integer value");
            break;
          }
          if (t.end < a_.tz.source.size() && is_ident_char(static_cast<unsigned char>(a_.tz.source[t.end]))) lua += ' ';
          a_.out[k] = lua;
          break;
        }
        case Kind::String: {
          if (t.unterminated) break;
          if (t.prefix.find('f') != std::string::npos) {
            refuse(t, "f-string", "write the text, or build it in Lua with .. and string.format");
            break;
          }
          std::string lua = lua_string(t, a_.tz.source);
          const std::size_t open = t.prefix.size() + (t.triple ? 3 : 1);
          StringValue v = decode_string(
              std::string_view(a_.tz.source).substr(t.begin + open, t.end - t.begin - open - (t.triple ? 3 : 1)),
              t.prefix.find('r') != std::string::npos, t.prefix.find('b') != std::string::npos);
          if (v.named_escape) refuse(t, "'\\N{...}' escape in a string", "write the character itself");
          if (after && after->kind == Kind::String) {
            lua += " ..";
            if (t.end < a_.tz.source.size() && !std::isspace(static_cast<unsigned char>(a_.tz.source[t.end]))) lua += ' ';
          }
          a_.out[k] = lua;
          break;
        }
        case Kind::Op:
          translate_op(st, p, before, after, refuse);
          break;
        default:
          break;
      }
    }
  }

  /// A name of the deck: math's names imported bare become math.NAME, built-ins called become py.NAME.
  void translate_name(int k, const Token* before, const Token* after) {
    const std::string& name = t_[k].text;
    if (before && is_op(*before, ".")) return;
    if (after && is_op(*after, "=")) return;  // a keyword argument or an assignment's target
    if (math_names_.count(name) && !shadowed(name)) a_.pre[k] = (math_local_ ? "math." : "py.math.") + a_.pre[k];
    else if (after && is_op(*after, "(") && builtin_names().count(name) && !shadowed(name)) a_.pre[k] = "py." + a_.pre[k];
  }

  /// True if the '(' at position o of `st` is the call of str(...).
  bool is_str_call(const Statement& st, std::size_t o) const {
    return o >= 1 && is_name(t_[st.toks[o - 1]], "str") && !shadowed("str");
  }

  /// TEXT op OPERAND (the operator at position p, after string literals) -> call(TEXT, OPERAND).
  void text_call(const Statement& st, std::size_t p, const char* call) {
    std::size_t q = p - 1;
    while (q > 0 && t_[st.toks[q - 1]].kind == Kind::String) --q;
    const std::size_t last = primary_end(st, p + 1);
    a_.pre[st.toks[q]] = call + a_.pre[st.toks[q]];
    a_.out[st.toks[p]] = ",";
    a_.post[st.toks[last]] += ")";
    stringy_end_.insert(st.toks[last]);
  }

  /// Position of the last token of the operand starting at position q: a name, number, text or bracket,
  /// with its calls, subscripts and attributes.
  std::size_t primary_end(const Statement& st, std::size_t q) const {
    const std::size_t n = st.toks.size();
    if (q >= n) return n - 1;
    const Token& t = t_[st.toks[q]];
    if ((is_op(t, "-") || is_op(t, "+")) && q + 1 < n) return primary_end(st, q + 1);
    std::size_t e = (t.kind == Kind::Op && t.match > st.toks[q]) ? pos_of(st, t.match) : q;
    while (e + 1 < n) {
      const Token& u = t_[st.toks[e + 1]];
      if ((is_op(u, "(") || is_op(u, "[")) && u.match > st.toks[e + 1]) e = pos_of(st, u.match);
      else if (is_op(u, ".") && e + 2 < n && t_[st.toks[e + 2]].kind == Kind::Name) e += 2;
      else break;
    }
    return e;
  }

  /// Methods with a Lua spelling: 'text'.format(...), 'sep'.join(list), L.append(x), math.NAME.
  /// False if the '.' at position p is none of them (it is then refused).
  bool method(Statement& st, std::size_t p, const Token* before, const Token* after) {
    if (!before || !after || after->kind != Kind::Name) return false;
    if (before->kind == Kind::Name && before->text == "math" && (p < 2 || !is_op(t_[st.toks[p - 2]], ".")))
      return math_module_names().count(after->text) > 0;
    if (p + 2 >= st.toks.size() || !is_op(t_[st.toks[p + 2]], "(")) return false;
    const int dot = st.toks[p], name = st.toks[p + 1], open = st.toks[p + 2], close = t_[open].match;
    if (close < 0) return false;
    const bool empty = close == st.toks[p + 3 < st.toks.size() ? p + 3 : p + 2];
    if (before->kind == Kind::String && (after->text == "format" || after->text == "join")) {
      std::size_t q = p - 1;
      while (q > 0 && t_[st.toks[q - 1]].kind == Kind::String) --q;
      a_.pre[st.toks[q]] = "py." + after->text + "(" + a_.pre[st.toks[q]];
      a_.out[dot] = a_.out[name] = "";
      a_.out[open] = empty ? "" : ", ";
      skip_[name] = 1;
      stringy_end_.insert(close);
      return true;
    }
    if (before->kind == Kind::Name && after->text == "append" && !empty && (p < 2 || !is_op(t_[st.toks[p - 2]], "."))) {
      a_.pre[st.toks[p - 1]] = "table.insert(" + a_.pre[st.toks[p - 1]];
      a_.out[dot] = a_.out[name] = "";
      a_.out[open] = ", ";
      skip_[name] = 1;
      return true;
    }
    return false;
  }

  /// NAME[i] with a 0-based Python index: NAME[i + 1]; NAME[-n]: NAME[#NAME + 1 - n]; a text key stays.
  template <class Refuse>
  void subscript(Statement& st, std::size_t p, const Token* before, Refuse& refuse) {
    const Token& t = t_[st.toks[p]];
    const std::string what = before->kind == Kind::Name ? before->text + "[...]" : "[...]";
    if (t.match < 0) return;
    const std::size_t c = pos_of(st, t.match);
    bool plain = c > p + 1;
    for (std::size_t q = p + 1; q < c && plain; ++q) {
      const Token& u = t_[st.toks[q]];
      if (u.kind == Kind::Op && u.match > st.toks[q]) q = pos_of(st, u.match);
      else if (is_op(u, ":") || is_op(u, ",")) plain = false;
    }
    if (!plain) {
      refuse(t, "slice or several indices in '" + what + "'", "write the values out, or finish by hand in Lua");
      return;
    }
    const Token& first = t_[st.toks[p + 1]];
    const bool integer = c == p + 2 && first.kind == Kind::Number &&
                         first.text.find_first_not_of("0123456789") == std::string::npos;
    if (c == p + 2 && first.kind == Kind::String) return;
    if (integer) {
      a_.out[st.toks[p + 1]] = std::to_string(std::stoll(first.text) + 1);
      skip_[st.toks[p + 1]] = 1;
      return;
    }
    if (c == p + 3 && is_op(first, "-") && t_[st.toks[p + 2]].kind == Kind::Number && before->kind == Kind::Name &&
        t_[st.toks[p + 2]].text.find_first_not_of("0123456789") == std::string::npos) {
      a_.out[st.toks[p + 1]] = "#" + before->text + " + 1 -";
      skip_[st.toks[p + 1]] = 1;
      return;
    }
    a_.pre[st.toks[p + 1]] = "(" + a_.pre[st.toks[p + 1]];
    a_.post[st.toks[c - 1]] = ") + 1" + a_.post[st.toks[c - 1]];
  }

  /// [E for x in I] and [E for x in I if C]: py.comp(function(x) return E end, I, function(x) return C end).
  /// False if the list at position p is a plain list.
  template <class Refuse>
  bool comprehension(Statement& st, std::size_t p, Refuse& refuse) {
    const std::size_t c = pos_of(st, t_[st.toks[p]].match);
    std::size_t at_for = 0, at_if = 0;
    int n_for = 0;
    for (std::size_t q = p + 1; q < c; ++q) {
      const Token& u = t_[st.toks[q]];
      if (u.kind == Kind::Op && u.match > st.toks[q]) {
        q = pos_of(st, u.match);
        continue;
      }
      if (is_name(u, "for")) {
        if (!n_for++) at_for = q;
      } else if (is_name(u, "if") && n_for && !at_if) at_if = q;
    }
    if (!n_for) return false;
    const Token& open = t_[st.toks[p]];
    if (n_for > 1 || at_for == p + 1 || at_for + 3 >= c || t_[st.toks[at_for + 1]].kind != Kind::Name ||
        !is_name(t_[st.toks[at_for + 2]], "in") || (at_if && at_if == at_for + 3) || at_if + 1 == c) {
      refuse(open, "list comprehension in another form than [value for x in values if condition]",
             "write the values out, or build the table with a Lua loop");
      return true;
    }
    const std::string& x = t_[st.toks[at_for + 1]].text;
    a_.out[st.toks[p]] = "py.comp(function(" + x + ") return ";
    a_.out[st.toks[at_for]] = "end,";
    a_.out[st.toks[at_for + 1]] = a_.out[st.toks[at_for + 2]] = "";
    for (std::size_t q : {at_for, at_for + 1, at_for + 2}) skip_[st.toks[q]] = 1;
    if (at_if) {
      a_.out[st.toks[at_if]] = ", function(" + x + ") return";
      skip_[st.toks[at_if]] = 1;
      a_.out[st.toks[c]] = " end)";
    } else {
      a_.out[st.toks[c]] = ")";
    }
    return true;
  }

  template <class Refuse>
  void translate_op(Statement& st, std::size_t p, const Token* before, const Token* after, Refuse& refuse) {
    const int k = st.toks[p];
    const Token& t = t_[k];
    const std::string& op = t.text;
    if (op == "(") {
      if (t.match < 0) return;
      const std::size_t c = pos_of(st, t.match);
      if (callable_before(before)) {
        const bool attribute = p >= 2 && is_op(t_[st.toks[p - 2]], ".");
        if (before->kind == Kind::Name && attribute) {
          // a method or module function: the '.' decided
        } else if (before->kind == Kind::Name && is_upper_name(before->text) && !functions_.count(before->text)) {
          a_.out[k] = "{";
          a_.out[t.match] = "}";
          for (const auto& [a0, a1] : arguments(st, p, c)) {
            const Token& f = t_[st.toks[a0]];
            if (is_op(f, "*") || is_op(f, "**"))
              refuse(f, "argument unpacking '" + f.text + "' in " + before->text + "(...)",
                     "write the keywords out: KEY=value");
            else if (!(f.kind == Kind::Name && a0 + 1 <= a1 && is_op(t_[st.toks[a0 + 1]], "=")))
              refuse(f, "positional argument in " + before->text + "(...)",
                     "code_aster commands take keywords only: write KEY=value");
          }
        } else if (before->kind == Kind::Name) {
          if (before->text != "exec" && before->text != "eval" && !is_lua_only_reserved(before->text) &&
              !callable_name(before->text))
            refuse(*before, "Python function call '" + before->text + "'", hint_for_function(before->text));
        } else {
          refuse(t, "call of an expression", "compute the value and write it, or finish in Lua");
        }
        return;
      }
      if (c == p + 1 || has_top_comma(st, p, c)) {  // a tuple: (), ('A',), (1, 2)
        a_.out[k] = "{";
        a_.out[t.match] = "}";
      }
      return;
    }
    if (op == "[") {
      if (callable_before(before) && before->kind == Kind::Name && t.match >= 0 && table_cell(st, p)) return;
      if (callable_before(before)) {
        subscript(st, p, before, refuse);
        return;
      }
      if (t.match >= 0 && comprehension(st, p, refuse)) return;
      if (t.match >= 0) {
        a_.out[k] = "{";
        a_.out[t.match] = "}";
      }
      return;
    }
    if (op == "{") {
      refuse(t, "dict or set '{...}'", "use _F(...) for a factor keyword, or build a Lua table by hand");
      return;
    }
    if (op == "." && method(st, p, before, after)) return;
    if (op == "%" && before && before->kind == Kind::String) {  // 'text %d' % v, 'text %s %s' % (a, b)
      text_call(st, p, "py.fmt(");  // a tuple becomes a table
      return;
    }
    if (op == "*" && before && before->kind == Kind::String && after &&
        (after->kind == Kind::Number || after->kind == Kind::Name || is_op(*after, "("))) {
      text_call(st, p, "string.rep(");  // '-' * 80
      return;
    }
    if (op == ".") {
      std::string what = (before && before->kind == Kind::Name ? before->text : "") + "." +
                         (after && after->kind == Kind::Name ? after->text : "");
      const bool call = p + 2 < st.toks.size() && is_op(t_[st.toks[p + 2]], "(");
      refuse(t, std::string(call ? "method call '" : "attribute access '") + what + (call ? "()'" : "'"),
             "compute the value and write it, or finish in Lua (lunaster results have no Python methods)");
      return;
    }
    if (op == "**") a_.out[k] = "^";
    else if (op == "!=") a_.out[k] = "~=";
    else if (op == "+") {
      const bool text_before = before && (before->kind == Kind::String || stringy_end_.count(st.toks[p - 1]) ||
                                          (is_op(*before, ")") && p >= 1 && is_str_call(st, pos_of(st, before->match))));
      const bool text_after = after && (after->kind == Kind::String || (is_name(*after, "str") && !shadowed("str")));
      const bool unary = !before || (before->kind == Kind::Op && before->text != ")" && before->text != "]" &&
                                     before->text != "}") ||
                         (before->kind == Kind::Name && is_python_keyword(before->text) && before->text != "True" &&
                          before->text != "False" && before->text != "None");
      if (unary) a_.out[k] = "";  // +x: Lua has no unary plus
      else if (text_before || text_after)
        a_.out[k] = before->kind == Kind::Number && t.begin == before->end ? " .." : "..";  // 80.. would read as a number
    } else if (op == "=") {
      // keyword argument of a command call: fine; the statement's own '=' is checked by the form.
    } else if (op == "&" || op == "|" || op == "^" || op == "~" || op == "<<" || op == ">>") {
      refuse(t, "bitwise operator '" + op + "'", "compute the value and write it, or finish in Lua");
    } else if (op.size() >= 2 && op.back() == '=' && op != "==" && op != "<=" && op != ">=" && p == 1 &&
               before->kind == Kind::Name && op != "&=" && op != "|=" && op != "^=" && op != "<<=" && op != ">>=" &&
               op != "@=") {
      // X += v -> X = X + v
      std::string arithmetic = op.substr(0, op.size() - 1);
      if (arithmetic == "**") arithmetic = "^";
      if (arithmetic == "+" && after && after->kind == Kind::String) arithmetic = "..";
      a_.out[k] = "= " + before->text + " " + arithmetic;
    } else if (op.size() >= 2 && op.back() == '=' && op != "==" && op != "<=" && op != ">=") {
      refuse(t, "augmented assignment '" + op + "'",
             "write the assignment out: X = X " + op.substr(0, op.size() - 1) + " value");
    } else if (op == ":" || op == "->" || op == ":=") {
      if (st.reasons.empty())  // otherwise part of a lambda, subscript or dict already refused
        refuse(t, "'" + op + "' (slice, annotation or assignment expression)", "not translatable: finish by hand in Lua");
    } else if (op == "@" || op == "...") {
      refuse(t, "operator '" + op + "'", "not translatable: finish by hand in Lua");
    }
  }

  /// A simple statement is `NAME[, NAME...] = value[, value...]` or a command call `NAME(...)`.
  template <class Refuse>
  void check_statement_form(Statement& st, Refuse& refuse) {
    const bool others = !st.reasons.empty();
    // split at top-level ';'
    std::size_t start = 0;
    const std::size_t n = st.toks.size();
    for (std::size_t p = 0; p <= n; ++p) {
      if (p < n) {
        const Token& t = t_[st.toks[p]];
        if (t.kind == Kind::Op && t.match > st.toks[p] && std::strchr("([{", t.text[0])) {
          p = pos_of(st, t.match);
          continue;
        }
        if (!is_op(t, ";")) continue;
      }
      if (p > start) check_simple(st, start, p - 1, others, refuse);
      start = p + 1;
    }
  }

  template <class Refuse>
  void check_simple(Statement& st, std::size_t a, std::size_t b, bool others, Refuse& refuse) {
    std::vector<std::size_t> eqs;
    std::vector<std::size_t> commas;
    for (std::size_t p = a; p <= b; ++p) {
      const Token& t = t_[st.toks[p]];
      if (t.kind == Kind::Op && t.match > st.toks[p] && std::strchr("([{", t.text[0])) {
        p = pos_of(st, t.match);
        continue;
      }
      if (is_op(t, "=")) eqs.push_back(p);
      if (is_op(t, ",")) commas.push_back(p);
    }
    const Token& first = t_[st.toks[a]];
    if (eqs.size() > 1) {
      refuse(first, "chained assignment 'A = B = value'", "write one assignment per name");
      return;
    }
    if (eqs.empty()) {
      // a command call statement, a function or method call, X += value
      const Token& last = t_[st.toks[b]];
      const bool call = first.kind == Kind::Name && a + 1 <= b && is_op(t_[st.toks[a + 1]], "(") &&
                        t_[st.toks[a + 1]].match == st.toks[b] && is_op(last, ")");
      const bool method_call = first.kind == Kind::Name && a + 2 <= b && is_op(t_[st.toks[a + 1]], ".") && is_op(last, ")");
      const Token* second = a + 1 <= b ? &t_[st.toks[a + 1]] : nullptr;
      const bool augmented = first.kind == Kind::Name && second && second->kind == Kind::Op && second->text.size() >= 2 &&
                             second->text.back() == '=' && second->text != "==" && second->text != "<=" &&
                             second->text != ">=" && second->text != "!=";
      if (augmented || method_call || (call && (is_upper_name(first.text) || callable_name(first.text)))) return;
      if (!others)
        refuse(first, "statement that is neither an assignment nor a command call",
               "drop it, or finish by hand in Lua");
      return;
    }
    const std::size_t e = eqs[0];
    // targets: NAME (, NAME)*
    std::size_t n_targets = 0;
    bool names_only = e > a;
    for (std::size_t p = a; p < e; ++p) {
      const Token& t = t_[st.toks[p]];
      const bool want_name = (p - a) % 2 == 0;
      if (want_name ? t.kind != Kind::Name || is_python_keyword(t.text) : !is_op(t, ",")) names_only = false;
      if (want_name) ++n_targets;
    }
    if (e > a && is_op(t_[st.toks[e - 1]], ",")) names_only = false;
    if (first.kind == Kind::Name && a + 1 < e && is_op(t_[st.toks[a + 1]], "[") &&
        t_[st.toks[a + 1]].match == st.toks[e - 1]) {  // L[i] = value
      names_only = true;
      n_targets = 1;
    }
    if (!names_only) {
      if (!others) refuse(first, "assignment to something else than a name", "assign to a plain name");
      return;
    }
    if (e == b) {
      refuse(first, "assignment without a value", "write the value after '='");
      return;
    }
    std::size_t rhs_commas = 0;
    for (auto c : commas)
      if (c > e) ++rhs_commas;
    if (n_targets == 1 && rhs_commas > 0)
      refuse(first, "tuple without parentheses", "put the values in parentheses: X = (a, b)");
    else if (n_targets > 1 && rhs_commas + 1 != n_targets)
      refuse(first, "unpacking assignment", "write one assignment per name");
  }
};

Analysis analyse(std::string_view text) {
  Analysis a;
  a.tz = tokenize(text);
  Translator(a).run();
  return a;
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> lines;
  std::size_t b = 0;
  while (true) {
    std::size_t e = s.find('\n', b);
    if (e == std::string::npos) {
      lines.push_back(s.substr(b));
      break;
    }
    lines.push_back(s.substr(b, e - b));
    b = e + 1;
  }
  return lines;
}

std::string comment_text(const std::string& python_comment, char before) {
  // '#' -> '--'; keep '--[[' / '--[=[' from opening a Lua long comment
  std::string rest = python_comment.substr(1);
  std::string out = before == '-' ? " --" : "--";
  if (!rest.empty() && rest[0] == '[') {
    std::size_t k = 1;
    while (k < rest.size() && rest[k] == '=') ++k;
    if (k < rest.size() && rest[k] == '[') out += ' ';
  }
  return out + rest;
}

// ---- check_comm: keywords against the catalogue ----

std::vector<std::string> declared_names(const catalog::Keyword& spec) {
  std::vector<std::string> names;
  for (const auto& c : spec.children) names.push_back(c.name);
  for (const auto& b : spec.blocks)
    for (const auto& k : b.keywords)
      if (std::find(names.begin(), names.end(), k.name) == names.end()) names.push_back(k.name);
  return names;
}

class Checker {
 public:
  Checker(const std::vector<Token>& tokens, const std::set<std::string>& functions, std::vector<CommIssue>& issues)
      : issues_(issues), functions_(functions) {
    for (int k = 0; k < static_cast<int>(tokens.size()); ++k)
      if (significant(tokens[k])) {
        index_of_.push_back(k);
        sig_.push_back(&tokens[k]);
      }
    pos_.assign(tokens.size(), 0);
    for (std::size_t p = 0; p < sig_.size(); ++p) pos_[index_of_[p]] = p;
  }

  void run() {
    for (std::size_t p = 0; p + 1 < sig_.size(); ++p) {
      const Token& t = *sig_[p];
      if (t.kind != Kind::Name || !is_upper_name(t.text) || t.text == "_F" || functions_.count(t.text)) continue;
      if (p > 0 && (is_op(*sig_[p - 1], ".") || is_name(*sig_[p - 1], "def") || is_name(*sig_[p - 1], "class")))
        continue;
      const Token& o = *sig_[p + 1];
      if (!is_op(o, "(") || o.match < 0) continue;
      const auto* spec = catalog::find_command(t.text);
      if (!spec) {
        std::vector<std::string> names;
        for (const auto& c : catalog::all_commands()) names.push_back(c.name);
        const std::string s = catalog::closest_name(t.text, names);
        issues_.push_back({t.line, "unknown command " + t.text + (s.empty() ? "" : " (did you mean " + s + "?)"),
                           "lunaster's catalogue has no such command (`lunaster help` lists them): remove it or "
                           "finish by hand"});
        continue;
      }
      check_arguments(*spec, spec->body, p + 1, pos_.at(o.match), "", true);
    }
  }

 private:
  std::vector<CommIssue>& issues_;
  const std::set<std::string>& functions_;
  std::vector<const Token*> sig_;
  std::vector<int> index_of_;
  std::vector<std::size_t> pos_;  ///< token index -> position in sig_

  bool opener(std::size_t p) const {
    const Token& t = *sig_[p];
    return t.kind == Kind::Op && t.match > index_of_[p] && std::strchr("([{", t.text[0]);
  }

  std::vector<std::pair<std::size_t, std::size_t>> items(std::size_t o, std::size_t c) const {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    std::size_t start = o + 1;
    for (std::size_t p = o + 1; p < c; ++p) {
      if (opener(p)) {
        p = pos_.at(sig_[p]->match);
        continue;
      }
      if (is_op(*sig_[p], ",")) {
        if (p > start) out.push_back({start, p - 1});
        start = p + 1;
      }
    }
    if (c > start) out.push_back({start, c - 1});
    return out;
  }

  /// The '(' positions of the _F calls a factor keyword's value is made of ([a, b] inclusive).
  void factor_calls(std::size_t a, std::size_t b, std::vector<std::size_t>& calls) const {
    if (a > b) return;
    const Token& f = *sig_[a];
    if (is_name(f, "_F") && a + 1 <= b && is_op(*sig_[a + 1], "(") && sig_[a + 1]->match == index_of_[b]) {
      calls.push_back(a + 1);
      return;
    }
    if ((is_op(f, "(") || is_op(f, "[")) && f.match == index_of_[b]) {
      for (const auto& [x, y] : items(a, b)) factor_calls(x, y, calls);
    }
  }

  /// Every declaration of factor `name` in `spec` (its children and all its blocks) as one
  /// factor whose children and blocks are those of all the declarations.
  static catalog::Keyword merged_declarations(const catalog::Keyword& spec, const catalog::Keyword& first) {
    const std::string& name = first.name;
    std::vector<const catalog::Keyword*> found = {&first};
    for (const auto& child : spec.children)
      if (child.name == name && child.is_factor && &child != &first) found.push_back(&child);
    for (const auto& block : spec.blocks)
      for (const auto& kw : block.keywords)
        if (kw.name == name && kw.is_factor && &kw != &first) found.push_back(&kw);
    catalog::Keyword merged = *found.front();
    for (std::size_t k = 1; k < found.size(); ++k) {
      merged.children.insert(merged.children.end(), found[k]->children.begin(), found[k]->children.end());
      merged.blocks.insert(merged.blocks.end(), found[k]->blocks.begin(), found[k]->blocks.end());
    }
    return merged;
  }

  void check_arguments(const catalog::CommandSpec& command, const catalog::Keyword& spec, std::size_t o,
                       std::size_t c, const std::string& prefix, bool top) {
    for (const auto& [a, b] : items(o, c)) {
      const Token& key = *sig_[a];
      if (key.kind != Kind::Name || a + 1 > b || !is_op(*sig_[a + 1], "=")) continue;
      if (top && key.text == "reuse") {
        if (!command.reuse_allowed)
          issues_.push_back({key.line, command.name + ": reuse is not accepted (" + command.name +
                                           " always creates a new concept)",
                             "drop reuse and name the result"});
        continue;
      }
      const auto* kw = catalog::find_declared(spec, key.text);
      const std::string path = prefix.empty() ? key.text : prefix + "/" + key.text;
      if (!kw && !spec.other_keywords.empty()) continue;  // a named value (FORMULE's)
      if (!kw) {
        const std::string s = catalog::closest_name(key.text, declared_names(spec));
        issues_.push_back({key.line,
                           command.name + ": unknown keyword " + path + (s.empty() ? "" : " (did you mean " + s + "?)"),
                           "`lunaster help " + command.name + "` lists its keywords; remove it or finish by hand"});
        continue;
      }
      if (!kw->is_factor) continue;
      // A factor declared in several blocks (DEFI_CONTACT's ZONE, one per FORMULATION) takes the
      // keywords of every declaration: which block applies is decided at run time.
      const catalog::Keyword merged = merged_declarations(spec, *kw);
      std::vector<std::size_t> calls;
      factor_calls(a + 2, b, calls);
      for (std::size_t i = 0; i < calls.size(); ++i) {
        // occurrences are numbered where the factor may repeat, as in the run-time keyword paths
        const std::string sub = kw->max_occurs != 1 ? path + "[" + std::to_string(i + 1) + "]" : path;
        check_arguments(command, merged, calls[i], pos_.at(sig_[calls[i]]->match), sub, false);
      }
    }
  }
};

}  // namespace

CommConversion convert_comm(std::string_view text) {
  Analysis a = analyse(text);
  std::string lua;
  lua.reserve(a.tz.source.size() + a.tz.source.size() / 8);
  std::size_t at = 0;
  for (std::size_t k = 0; k < a.tz.tokens.size(); ++k) {
    const Token& t = a.tz.tokens[k];
    lua.append(a.tz.source, at, t.begin - at);
    if (t.kind == Kind::Comment) lua += comment_text(t.text, lua.empty() ? '\0' : lua.back());
    else if (t.kind == Kind::Continuation) lua += t.text.substr(1);
    else lua += a.pre[k] + a.out[k] + a.post[k];
    at = t.end;
  }
  lua.append(a.tz.source, at, std::string::npos);

  // Refused lines: the marker and the source line, its comment in Lua spelling.
  std::vector<std::string> out_lines = split_lines(lua);
  const std::vector<std::string> src_lines = split_lines(a.tz.source);
  if (out_lines.size() != src_lines.size()) out_lines = src_lines;  // never happens; keeps the alignment promise
  std::vector<std::size_t> line_start(src_lines.size() + 1, 0);
  for (std::size_t l = 1; l < src_lines.size(); ++l) line_start[l] = line_start[l - 1] + src_lines[l - 1].size() + 1;
  std::vector<std::ptrdiff_t> hash_col(src_lines.size(), -1);
  for (const Token& t : a.tz.tokens)
    if (t.kind == Kind::Comment) hash_col[t.line - 1] = static_cast<std::ptrdiff_t>(t.begin - line_start[t.line - 1]);
  for (std::size_t l = 0; l < src_lines.size(); ++l) {
    if (l + 1 >= a.refused_line.size() || !a.refused_line[l + 1]) continue;
    const std::string& src = src_lines[l];
    if (src.find_first_not_of(" \t\r\f\v") == std::string::npos) continue;
    std::string line = src;
    if (hash_col[l] >= 0) line = src.substr(0, hash_col[l]) + "--" + src.substr(hash_col[l] + 1);
    out_lines[l] = kMarker + line;
  }
  CommConversion result;
  for (std::size_t l = 0; l < out_lines.size(); ++l) {
    if (l) result.lua += '\n';
    result.lua += out_lines[l];
  }
  result.refused = std::move(a.refused);
  return result;
}

std::vector<CommIssue> check_comm(std::string_view text) {
  Analysis a = analyse(text);
  std::vector<CommIssue> issues = a.refused;
  Checker(a.tz.tokens, a.functions, issues).run();
  std::stable_sort(issues.begin(), issues.end(), [](const CommIssue& x, const CommIssue& y) { return x.line < y.line; });
  return issues;
}

}  // namespace lunaster::lua
