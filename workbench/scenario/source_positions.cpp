#include "workbench/scenario/source_positions.hpp"

#include <algorithm>
#include <cctype>

namespace rb::scenario {
namespace {

bool identStart(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool identChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// The level of a long bracket opening at i ("[[" 0, "[==[" 2), -1 when text[i..] is not one.
int longBracketLevel(std::string_view t, std::size_t i) {
  if (i >= t.size() || t[i] != '[') return -1;
  std::size_t j = i + 1;
  while (j < t.size() && t[j] == '=') ++j;
  return j < t.size() && t[j] == '[' ? static_cast<int>(j - i - 1) : -1;
}

// The offset after the long bracket of `level` opened at i; t.size() when it never closes.
std::size_t skipLongBracket(std::string_view t, std::size_t i, int level) {
  const std::string close = "]" + std::string(static_cast<std::size_t>(level), '=') + "]";
  const std::size_t end = t.find(close, i + static_cast<std::size_t>(level) + 2);
  return end == std::string_view::npos ? t.size() : end + close.size();
}

// The offset after the quoted string opened at i (t[i] is ' or "); t.size() when unterminated.
std::size_t skipQuoted(std::string_view t, std::size_t i) {
  const char q = t[i];
  for (std::size_t j = i + 1; j < t.size(); ++j) {
    if (t[j] == '\\') {
      ++j;
    } else if (t[j] == q || t[j] == '\n') {
      return j + 1;
    }
  }
  return t.size();
}

// Skips white space and comments from i.
std::size_t skipTrivia(std::string_view t, std::size_t i) {
  while (i < t.size()) {
    if (std::isspace(static_cast<unsigned char>(t[i])) != 0) {
      ++i;
    } else if (t.compare(i, 2, "--") == 0) {
      const int level = longBracketLevel(t, i + 2);
      if (level >= 0) {
        i = skipLongBracket(t, i + 2, level);
      } else {
        const std::size_t nl = t.find('\n', i);
        i = nl == std::string_view::npos ? t.size() : nl + 1;
      }
    } else {
      break;
    }
  }
  return i;
}

// Keywords that open a block closed by `end` (while and for open theirs with `do`), and the
// repeat ... until pair: a function written as a value may hold commas at bracket level 0.
int blockChange(std::string_view word) {
  if (word == "function" || word == "if" || word == "do" || word == "repeat") return 1;
  if (word == "end" || word == "until") return -1;
  return 0;
}

// From the start of a value, the offset of the ',' ';' or '}' that ends it at this table's
// level; t.size() when the text ends first.
std::size_t skipValue(std::string_view t, std::size_t i) {
  int brackets = 0, blocks = 0;
  while (i < t.size()) {
    i = skipTrivia(t, i);
    if (i >= t.size()) break;
    const char c = t[i];
    if (c == '"' || c == '\'') {
      i = skipQuoted(t, i);
    } else if (const int level = longBracketLevel(t, i); level >= 0) {
      i = skipLongBracket(t, i, level);
    } else if (identStart(c)) {
      std::size_t j = i;
      while (j < t.size() && identChar(t[j])) ++j;
      const bool member = i > 0 && (t[i - 1] == '.' || t[i - 1] == ':');
      if (!member) blocks += blockChange(t.substr(i, j - i));
      i = j;
    } else if (c == '(' || c == '[' || c == '{') {
      ++brackets;
      ++i;
    } else if (c == ')' || c == ']' || c == '}') {
      if (brackets == 0) return i;  // '}' of the enclosing table (or unbalanced text)
      --brackets;
      ++i;
    } else if ((c == ',' || c == ';') && brackets == 0 && blocks <= 0) {
      return i;
    } else {
      ++i;
    }
  }
  return t.size();
}

// A key written as ["name"] at i: the name and the offset after ']'; nullopt otherwise.
std::optional<std::pair<std::string, std::size_t>> bracketKey(std::string_view t, std::size_t i) {
  if (longBracketLevel(t, i) >= 0) return std::nullopt;
  std::size_t k = skipTrivia(t, i + 1);
  if (k >= t.size() || (t[k] != '"' && t[k] != '\'')) return std::nullopt;
  const std::size_t end = skipQuoted(t, k);
  if (end > t.size() || end < k + 2 || t[end - 1] != t[k]) return std::nullopt;
  std::string name(t.substr(k + 1, end - k - 2));
  if (name.find('\\') != std::string::npos) return std::nullopt;  // escapes: not decoded here
  k = skipTrivia(t, end);
  if (k >= t.size() || t[k] != ']') return std::nullopt;
  return std::make_pair(std::move(name), k + 1);
}

// '=' (not '==') at i after trivia: the offset of the value after it; nullopt otherwise.
std::optional<std::size_t> assignment(std::string_view t, std::size_t i) {
  i = skipTrivia(t, i);
  if (i >= t.size() || t[i] != '=' || (i + 1 < t.size() && t[i + 1] == '=')) return std::nullopt;
  return skipTrivia(t, i + 1);
}

}  // namespace

std::optional<TableEntries> scanTable(std::string_view text, std::size_t open) {
  if (open >= text.size() || text[open] != '{') return std::nullopt;
  TableEntries out;
  std::size_t i = open + 1;
  while (true) {
    i = skipTrivia(text, i);
    if (i >= text.size()) return std::nullopt;
    if (text[i] == '}') return out;
    std::size_t value = i;
    std::optional<std::string> key;
    if (identStart(text[i])) {
      std::size_t j = i;
      while (j < text.size() && identChar(text[j])) ++j;
      if (auto v = assignment(text, j)) {
        key = std::string(text.substr(i, j - i));
        value = *v;
      }
    } else if (text[i] == '[') {
      if (auto k = bracketKey(text, i))
        if (auto v = assignment(text, k->second)) {
          key = k->first;
          value = *v;
        }
    }
    if (key)
      out.fields.emplace_back(*key, value);
    else
      out.items.push_back(value);
    const std::size_t end = skipValue(text, value);
    if (end >= text.size()) return std::nullopt;
    if (text[end] == '}') return out;
    i = end + 1;
  }
}

std::vector<std::size_t> lineStarts(std::string_view text) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') starts.push_back(i + 1);
  return starts;
}

int lineOf(const std::vector<std::size_t>& starts, std::size_t offset) {
  const auto it = std::upper_bound(starts.begin(), starts.end(), offset);
  return static_cast<int>(it - starts.begin());
}

std::optional<std::size_t> constructorBrace(std::string_view text, int line,
                                            const std::string& kind) {
  if (line < 1 || kind.empty()) return std::nullopt;
  std::size_t begin = 0;
  for (int l = 1; l < line; ++l) {
    const std::size_t nl = text.find('\n', begin);
    if (nl == std::string_view::npos) return std::nullopt;
    begin = nl + 1;
  }
  const std::size_t nl = text.find('\n', begin);
  const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
  std::optional<std::size_t> found;
  int count = 0;
  for (std::size_t p = text.find(kind, begin); p != std::string_view::npos && p < end;
       p = text.find(kind, p + 1)) {
    const bool wordStart = p == 0 || (!identChar(text[p - 1]) && text[p - 1] != '.');
    const std::size_t after = p + kind.size();
    if (!wordStart || (after < text.size() && identChar(text[after]))) continue;
    std::size_t k = skipTrivia(text, after);
    if (k < text.size() && text[k] == '(') k = skipTrivia(text, k + 1);
    if (k < text.size() && text[k] == '{') {
      found = k;
      ++count;
    }
  }
  return count == 1 ? found : std::nullopt;
}

}  // namespace rb::scenario
