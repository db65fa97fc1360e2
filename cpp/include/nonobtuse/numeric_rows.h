// Plain numeric rows of a text file (the vertex, segment, element and face blocks of .node/.poly/.ele/.smesh/OFF
// files): the fast path of the readers in nonobtuse.io, which fall back to reading line by line, naming any
// problem by file and line, wherever this path refuses a block.
#pragma once
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace nonobtuse {

// The values, row after row, when `text` is `rows` lines (separated by '\n') each holding exactly `width`
// whitespace-separated (' ', '\t') plain decimal numbers, and every token of the columns `integer_columns` is an
// integer literal (no '.', 'e' or 'E') of magnitude below 2^53 (so read exactly). A number is an optional sign,
// digits with at most one '.', and an optional exponent; it is rounded correctly (std::from_chars), as Python's
// float() rounds it. nullopt for anything else (a comment, a blank or ragged row, any other character, nan, inf,
// a token that is not one whole number), for the caller's line reader to accept or to name.
// Cost: O(characters), one pass; no allocation but the result.
std::optional<std::vector<double>> parse_numeric_rows(std::string_view text, std::size_t rows, std::size_t width,
                                                      const std::vector<int>& integer_columns);

}  // namespace nonobtuse
