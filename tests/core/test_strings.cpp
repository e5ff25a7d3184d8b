#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "workbench/core/names.hpp"
#include "workbench/core/range.hpp"
#include "workbench/core/strings.hpp"

namespace {

enum class Colour { Red, Green };
constexpr std::array<rb::NameEntry<Colour>, 2> kColourNames = {{
    {Colour::Red, "red", "warm"},
    {Colour::Green, "green", ""},
}};
constexpr const auto& nameTable(Colour /*tag*/) {
  return kColourNames;
}

}  // namespace

TEST(Strings, FormatNumberIsPrintfG) {
  EXPECT_EQ(rb::formatNumber(0.001), "0.001");
  EXPECT_EQ(rb::formatNumber(2.1e11), "2.1e+11");
  EXPECT_EQ(rb::formatNumber(1e-6), "1e-06");
  EXPECT_EQ(rb::formatNumber(0.123456789), "0.123457");
  EXPECT_EQ(rb::formatNumber(0.123456789, 3), "0.123");
  EXPECT_EQ(rb::formatNumber(std::numeric_limits<double>::infinity()), "inf");
}

TEST(Strings, FormatNumberExactReadsBack) {
  EXPECT_EQ(rb::formatNumberExact(0.1), "0.1");
  for (double v : {1.0 / 3.0, 2.0 / 7.0, 1e-300, 123456789.123})
    EXPECT_EQ(std::strtod(rb::formatNumberExact(v).c_str(), nullptr), v);
}

TEST(Strings, ParseCsvReadsWhatCsvFieldWrites) {
  const std::string text = "a,b,c\r\n" + rb::csvField("x, y") + "," + rb::csvField("say \"hi\"") +
                           ",\n\n\"two\nlines\",,3\n";
  const auto rows = rb::parseCsv(text);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(rows[1], (std::vector<std::string>{"x, y", "say \"hi\"", ""}));
  EXPECT_EQ(rows[2], (std::vector<std::string>{"two\nlines", "", "3"}));
  EXPECT_TRUE(rb::parseCsv("").empty());
  // A last record without its line end, and an unterminated quote ends at the end of the text.
  EXPECT_EQ(rb::parseCsv("1,2").at(0), (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(rb::parseCsv("\"open,x").at(0), (std::vector<std::string>{"open,x"}));
}

TEST(Names, TableLookups) {
  static_assert(rb::nameOf(Colour::Green) == "green");
  static_assert(rb::parse<Colour>("red") == Colour::Red);
  static_assert(!rb::parse<Colour>("blue").has_value());
  EXPECT_EQ(rb::namesOf<Colour>(), (std::vector<std::string>{"red", "green"}));
  EXPECT_EQ(rb::helpOf<Colour>(), "red: warm");
}

TEST(Range, ContainsAndText) {
  const rb::Range closed{0.0, 0.5};
  const rb::Range open{0.0, 1.0, true, true};
  EXPECT_TRUE(closed.contains(0.5));
  EXPECT_FALSE(open.contains(1.0));
  EXPECT_FALSE(open.contains(0.0));
  EXPECT_FALSE(closed.contains(std::nan("")));
  EXPECT_EQ(closed.text(), "[0, 0.5]");
  EXPECT_EQ(open.text(), "(0, 1)");
  EXPECT_EQ((rb::Range{0.0, std::numeric_limits<double>::infinity(), true}).text(), "(0, inf)");
}

TEST(Strings, PathPartsSplitADatasetPathAfterItsRoot) {
  EXPECT_EQ(rb::pathParts("/bodies/ws1/y"), (std::vector<std::string>{"bodies", "ws1", "y"}));
  EXPECT_EQ(rb::pathParts("/vehicles/front/contact/ws1/left/Q"),
            (std::vector<std::string>{"vehicles", "front", "contact", "ws1", "left", "Q"}));
  EXPECT_EQ(rb::pathParts("/time"), (std::vector<std::string>{"time"}));
  EXPECT_EQ(rb::pathParts("/a//b/"), (std::vector<std::string>{"a", "", "b", ""}));
  EXPECT_TRUE(rb::pathParts("").empty());
}
