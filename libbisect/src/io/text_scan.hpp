// Line-oriented scanning for the text input formats (.poly, .poly2, OFF, ASCII STL): every token
// keeps the number of the line it came from, so that each error can say "FILE:LINE: what".
// The thesis listings put `--` comments anywhere on a line, headers included; OFF uses `#`.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::io {

// "name:line" (or just "name" when line <= 0), the prefix of every reader message.
std::string where(const std::string& source, int line);
// Throws InputError("name:line: what").
[[noreturn]] void fail(const std::string& source, int line, const std::string& what);

// Numbers in messages: short (%.6g) so that a message stays one readable line.
std::string fmt_num(double v);
std::string fmt_point(const Vec3& p);  // "(x, y, z)"
std::string fmt_point(const Vec2& p);  // "(x, y)"

// A token as a message may show it: bytes that are not printable ASCII become '?' (a binary file
// read as text must not put control characters on the user's terminal), long tokens are cut.
std::string printable(const std::string& token, std::size_t max_chars = 40);

// "1 region" / "3 regions".
std::string count_of(std::int64_t n, const std::string& singular, const std::string& plural);

// Reads one line at a time, drops the comment (from `comment` to the end of the line; none when
// `comment` is empty), splits on blanks and skips lines left empty.
class LineScanner {
public:
  LineScanner(std::istream& in, std::string source, std::string comment);

  // Moves to the next line holding at least one token; false at the end of the input.
  bool next();
  // Like next(), but the end of the input is an error: "the file ends before WHAT".
  void expect(const std::string& what);
  // Moves to the first line with data; an empty file, or one of only comments, is an error
  // saying that `what` was expected.
  void first(const std::string& what);

  int line() const { return line_; }
  std::size_t size() const { return tokens_.size(); }
  const std::string& token(std::size_t i) const { return tokens_[i]; }
  const std::vector<std::string>& tokens() const { return tokens_; }
  const std::string& source() const { return source_; }
  // The current line's tokens from `first` on, joined by blanks (for "extra data" messages).
  std::string rest(std::size_t first, std::size_t max_tokens = 8) const;

  // Token i of the current line as a whole number; `what` names it ("the node count of face 3").
  std::int64_t integer(std::size_t i, const std::string& what) const;
  // Token i as a finite real number: NaN and infinities are rejected, naming `what`.
  double real(std::size_t i, const std::string& what) const;

  [[noreturn]] void fail(const std::string& what) const;

private:
  std::istream& in_;
  std::string source_;
  std::string comment_;
  std::string text_;
  std::vector<std::string> tokens_;
  int line_ = 0;
};

// A token stream over LineScanner for grammars that are not one record per line (ASCII STL).
class TokenCursor {
public:
  explicit TokenCursor(LineScanner& lines) : lines_(lines) {}
  // The next token, or nullptr at the end of the input.
  const std::string* next();
  // Drops what is left of the current line (the free-text name after `solid`).
  void skip_rest_of_line() { pos_ = lines_.size(); }
  int line() const { return lines_.line(); }

private:
  LineScanner& lines_;
  std::size_t pos_ = 0;
  bool started_ = false;
};

// Whole-token numbers, independent of the C locale; false when the text is not one. A leading
// '+' is allowed. "nan" and "inf" parse (callers reject them by name); a real that overflows
// becomes an infinity, one that underflows becomes zero.
bool parse_real(const std::string& text, double& out);
bool parse_integer(const std::string& text, std::int64_t& out);

}  // namespace bisect::io
