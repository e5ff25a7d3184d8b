#pragma once
// Small string helpers shared by the modules: edit distance and "did you mean" suggestions for
// error messages, joining lists of names, numbers as message text.
#include <string>
#include <string_view>
#include <vector>

namespace rb {

// Optimal-string-alignment distance (Levenshtein plus adjacent transposition), ASCII
// case-insensitive: editDistance("rk5", "rk4") == 1, editDistance("bfd", "bdf") == 1.
int editDistance(std::string_view a, std::string_view b);

// The candidate closest to `word` for a "did you mean" hint, or "" when none is close enough.
// Close enough: distance <= max(1, word.size() / 3). Ties go to the earlier candidate.
std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates);

// The parts of a slash-separated path after its first character (a result file's dataset path):
// pathParts("/bodies/ws1/y") == {"bodies", "ws1", "y"}.
std::vector<std::string> pathParts(std::string_view path);

// Items separated by `sep`: join({"a", "b"}) == "a, b".
std::string join(const std::vector<std::string>& items, std::string_view sep = ", ");

// A CSV field: quoted when it holds a comma, a quote or a newline, quotes doubled, newlines
// written as spaces (one record per line, so line-based readers keep working).
std::string csvField(std::string_view s);

// The records of CSV text (RFC 4180: fields separated by commas, a quoted field may hold commas,
// doubled quotes and line breaks; CRLF or LF line ends). Empty lines are left out.
std::vector<std::vector<std::string>> parseCsv(std::string_view text);

// A number as message and attribute text, printf "%.*g" with `significant` digits: the shortest
// form a reader recognises (formatNumber(0.001) == "0.001", formatNumber(2.1e11) == "2.1e+11"),
// identical to what an std::ostream with its default precision (6) writes.
std::string formatNumber(double v, int significant = 6);
// The shortest "%.*g" text (6 to 17 digits) that reads back as the same double: a value as it
// would be typed (formatNumberExact(0.1) == "0.1", formatNumberExact(1.0 / 3) == "0.333...").
std::string formatNumberExact(double v);

}  // namespace rb
