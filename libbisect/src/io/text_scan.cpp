#include "io/text_scan.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <istream>
#include <system_error>

#include "bisect/errors.hpp"

namespace bisect::io {

std::string where(const std::string& source, int line) {
  return line > 0 ? source + ":" + std::to_string(line) : source;
}

void fail(const std::string& source, int line, const std::string& what) {
  throw InputError(where(source, line) + ": " + what);
}

// std::to_chars / from_chars rather than printf / strtod: those follow the C locale, and inside
// FreeCAD the locale may use a decimal comma.
std::string fmt_num(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 6);
  return std::string(buf, r.ptr);
}

std::string fmt_point(const Vec3& p) {
  return "(" + fmt_num(p.x()) + ", " + fmt_num(p.y()) + ", " + fmt_num(p.z()) + ")";
}

std::string fmt_point(const Vec2& p) { return "(" + fmt_num(p.x()) + ", " + fmt_num(p.y()) + ")"; }

std::string printable(const std::string& token, std::size_t max_chars) {
  std::string s;
  for (std::size_t i = 0; i < token.size() && i < max_chars; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    s += c >= 0x20 && c < 0x7f ? char(c) : '?';
  }
  if (token.size() > max_chars) s += "...";
  return s;
}

std::string count_of(std::int64_t n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

bool parse_real(const std::string& text, double& out) {
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+') ++first;  // from_chars refuses a leading '+'
  if (first == last || (text[0] == '+' && (*first == '-' || *first == '+'))) return false;
  const auto r = std::from_chars(first, last, out, std::chars_format::general);
  if (r.ptr != last) return false;
  if (r.ec == std::errc::result_out_of_range) {
    // Overflow is as unusable as an infinity (the caller rejects it); underflow is zero.
    bool underflow = true;
    const char* e = first;
    while (e != last && *e != 'e' && *e != 'E') ++e;
    if (e != last) {
      underflow = e + 1 != last && e[1] == '-';
    } else {
      for (const char* c = first; c != last && *c != '.'; ++c)
        if (*c >= '1' && *c <= '9') underflow = false;
    }
    out = underflow ? 0.0 : (*first == '-' ? -HUGE_VAL : HUGE_VAL);
    return true;
  }
  return r.ec == std::errc();
}

bool parse_integer(const std::string& text, std::int64_t& out) {
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+') ++first;
  if (first == last || (text[0] == '+' && *first == '-')) return false;
  const auto r = std::from_chars(first, last, out);
  return r.ec == std::errc() && r.ptr == last;
}

LineScanner::LineScanner(std::istream& in, std::string source, std::string comment)
    : in_(in), source_(std::move(source)), comment_(std::move(comment)) {}

bool LineScanner::next() {
  tokens_.clear();
  while (tokens_.empty()) {
    if (!std::getline(in_, text_)) return false;
    ++line_;
    if (line_ == 1 && text_.compare(0, 3, "\xEF\xBB\xBF") == 0) text_.erase(0, 3);  // UTF-8 BOM
    std::size_t end = text_.size();
    if (!comment_.empty()) end = std::min(end, text_.find(comment_));
    std::size_t i = 0;
    while (i < end) {
      while (i < end && std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
      const std::size_t start = i;
      while (i < end && !std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
      if (i > start) tokens_.emplace_back(text_, start, i - start);
    }
  }
  return true;
}

void LineScanner::expect(const std::string& what) {
  if (!next()) io::fail(source_, line_, "the file ends before " + what);
}

void LineScanner::first(const std::string& what) {
  if (next()) return;
  io::fail(source_, line_,
           (line_ == 0 ? "the file is empty" : "the file holds only comments and blank lines") + std::string(": expected ") +
               what);
}

std::string LineScanner::rest(std::size_t first, std::size_t max_tokens) const {
  std::string s;
  for (std::size_t i = first; i < tokens_.size() && i < first + max_tokens; ++i) {
    if (i > first) s += ' ';
    s += printable(tokens_[i]);
  }
  if (tokens_.size() > first + max_tokens) s += " ...";
  return s;
}

std::int64_t LineScanner::integer(std::size_t i, const std::string& what) const {
  std::int64_t v = 0;
  if (!parse_integer(tokens_[i], v)) {
    const std::string& t = tokens_[i];
    if (t.size() > 1 && t.find_first_not_of("0123456789", t[0] == '-' || t[0] == '+' ? 1 : 0) == std::string::npos)
      fail(what + " is out of range ('" + printable(t) + "')");
    double d = 0;
    if (parse_real(tokens_[i], d)) fail(what + " must be a whole number, not '" + printable(tokens_[i]) + "'");
    fail("expected a whole number for " + what + ", found '" + printable(tokens_[i]) + "'");
  }
  return v;
}

double LineScanner::real(std::size_t i, const std::string& what) const {
  double v = 0;
  if (!parse_real(tokens_[i], v)) fail("expected a number for " + what + ", found '" + printable(tokens_[i]) + "'");
  if (!std::isfinite(v)) fail(what + " is not a finite number ('" + printable(tokens_[i]) + "')");
  return v;
}

void LineScanner::fail(const std::string& what) const { io::fail(source_, line_, what); }

const std::string* TokenCursor::next() {
  if (!started_) {
    started_ = true;
    if (!lines_.next()) return nullptr;
    pos_ = 0;
  }
  while (pos_ >= lines_.size()) {
    if (!lines_.next()) return nullptr;
    pos_ = 0;
  }
  return &lines_.token(pos_++);
}

}  // namespace bisect::io
