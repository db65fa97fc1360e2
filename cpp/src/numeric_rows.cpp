// The fast path of the text readers: plain numeric rows parsed with std::from_chars (correctly rounded).
#include "nonobtuse/numeric_rows.h"

#include <charconv>
#include <cmath>

namespace nonobtuse {
namespace {

// 2^53: a literal below it rounds to itself; one at or above it may not (2^53 + 1 rounds to 2^53), and rounding is
// monotonic, so a value below 2^53 came from exactly that integer.
constexpr double kExactInteger = 9007199254740992.0;

bool is_space(char c) { return c == ' ' || c == '\t'; }

// One token [b, e): a plain decimal number, parsed whole into x; `integer` when it has no '.', 'e' or 'E'.
// std::from_chars takes no '+' and would take "inf", "nan" and hexadecimal forms: those are refused first.
bool parse_token(const char* b, const char* e, double& x, bool& integer) {
  integer = true;
  for (const char* c = b; c != e; ++c) {
    const bool digit = *c >= '0' && *c <= '9', sign = *c == '+' || *c == '-';
    const bool fraction = *c == '.' || *c == 'e' || *c == 'E';
    if (!digit && !sign && !fraction) return false;
    integer = integer && !fraction;
  }
  if (*b == '+') {
    ++b;
    if (b == e || *b == '+' || *b == '-') return false;
  }
  const auto [end, error] = std::from_chars(b, e, x);
  return error == std::errc() && end == e && std::isfinite(x);
}

}  // namespace

std::optional<std::vector<double>> parse_numeric_rows(std::string_view text, std::size_t rows, std::size_t width,
                                                      const std::vector<int>& integer_columns) {
  std::vector<bool> integral(width, false);
  for (int c : integer_columns)
    if (c >= 0 && static_cast<std::size_t>(c) < width) integral[c] = true;
  std::vector<double> values;
  values.reserve(rows * width);
  const char *p = text.data(), *end = p + text.size();
  for (std::size_t r = 0; r < rows; ++r) {
    const char* line_end = p;
    while (line_end != end && *line_end != '\n') ++line_end;
    std::size_t column = 0;
    for (const char* q = p; q != line_end;) {
      if (is_space(*q)) {
        ++q;
        continue;
      }
      const char* t = q;
      while (t != line_end && !is_space(*t)) ++t;
      double x;
      bool integer;
      if (column == width || !parse_token(q, t, x, integer)) return std::nullopt;
      if (integral[column] && (!integer || std::abs(x) >= kExactInteger)) return std::nullopt;
      values.push_back(x);
      ++column;
      q = t;
    }
    if (column != width) return std::nullopt;
    if (line_end == end && r + 1 < rows) return std::nullopt;  // fewer lines than rows
    p = line_end == end ? end : line_end + 1;
  }
  if (p != end) return std::nullopt;  // more lines than rows
  return values;
}

}  // namespace nonobtuse
