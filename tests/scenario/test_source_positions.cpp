// The lines of table entries: a problem with a key inside a plain table is reported at the key's
// own line (the scanner of source_positions.hpp and the converter that uses it).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "workbench/core/error.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/source_positions.hpp"

namespace fs = std::filesystem;
using rb::scenario::constructorBrace;
using rb::scenario::lineOf;
using rb::scenario::lineStarts;
using rb::scenario::scanTable;

namespace {

int lineOfOffset(const std::string& text, std::size_t offset) {
  return lineOf(lineStarts(text), offset);
}

std::string errorsOf(const std::string& name, const std::string& text) {
  const fs::path d = fs::temp_directory_path() / "rb_test_source_positions";
  fs::create_directories(d);
  const std::string p = (d / name).string();
  std::ofstream(p) << text;
  rb::scenario::LoadOptions o;
  o.root = RB_SOURCE_DIR;
  try {
    rb::scenario::loadScenario(p, o);
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "<no error>";
}

}  // namespace

TEST(SourcePositions, FieldsItemsAndBracketKeys) {
  const std::string t =
      "run {\n"
      "  duration = 1,  -- a comment with a { brace\n"
      "  [\"x.y\"] = { 1, 2 },\n"
      "  'item', \"it,em\";\n"
      "  s = [[ } , ]],\n"
      "  f = function(a, b) local c, d = a, b if c then return d end return c end,\n"
      "  last = 2 }\n";
  const auto brace = constructorBrace(t, 1, "run");
  ASSERT_TRUE(brace.has_value());
  const auto e = scanTable(t, *brace);
  ASSERT_TRUE(e.has_value());
  ASSERT_EQ(e->fields.size(), 5U);
  EXPECT_EQ(e->fields[0].first, "duration");
  EXPECT_EQ(lineOfOffset(t, e->fields[0].second), 2);
  EXPECT_EQ(e->fields[1].first, "x.y");
  EXPECT_EQ(t[e->fields[1].second], '{');
  EXPECT_EQ(e->fields[2].first, "s");
  EXPECT_EQ(e->fields[3].first, "f");
  EXPECT_EQ(e->fields[4].first, "last");
  EXPECT_EQ(lineOfOffset(t, e->fields[4].second), 7);
  ASSERT_EQ(e->items.size(), 2U);  // the commas in the string, the long string and the function
  EXPECT_EQ(lineOfOffset(t, e->items[1]), 4);
  const auto inner = scanTable(t, e->fields[1].second);
  ASSERT_TRUE(inner.has_value());
  EXPECT_EQ(inner->items.size(), 2U);
}

TEST(SourcePositions, ConstructorBraceNeedsOneCallOnTheLine) {
  EXPECT_TRUE(constructorBrace("x = 1\nrun({ a = 1 })\n", 2, "run").has_value());
  EXPECT_FALSE(constructorBrace("run(t)\n", 1, "run").has_value());  // a table from elsewhere
  // Two calls of one kind on one line cannot be told apart.
  EXPECT_FALSE(
      constructorBrace("tangent { length = 1 }, tangent { length = 2 }", 1, "tangent").has_value());
  EXPECT_FALSE(constructorBrace("myrun { a = 1 }", 1, "run").has_value());
  EXPECT_FALSE(constructorBrace("run { a = 1 }", 5, "run").has_value());
}

TEST(SourcePositions, IncompleteTextIsNotScanned) {
  EXPECT_FALSE(scanTable("{ a = 1, b = { 2", 0).has_value());
  EXPECT_FALSE(scanTable("a = 1", 0).has_value());
  EXPECT_FALSE(scanTable("{ s = \"unterminated }", 0).has_value());
}

// The converter: keys of a plain table nested in a block are reported at their own lines, list
// entries at theirs; a table built in code keeps the enclosing line.
TEST(SourcePositions, ProblemsAtTheKeysLine) {
  const std::string errors = errorsOf("keys.lua",
                                      "track { segments = { tangent { length = 100 } } }\n"   // 1
                                      "vehicle(require \"vehicles.manchester_wagon1\" {})\n"  // 2
                                      "contact { method = \"kec\" }\n"                        // 3
                                      "run {\n"                                               // 4
                                      "  duration = 0.1,\n"                                   // 5
                                      "  assessment = {\n"                                    // 6
                                      "    alpha = 5,\n"                                      // 7
                                      "    sections = {\n"                                    // 8
                                      "      { name = \"a\", from = 0, to = 50 },\n"          // 9
                                      "      { name = \"b\", from = 60, to = -1 },\n"         // 10
                                      "    },\n"                                              // 11
                                      "  },\n"                                                // 12
                                      "}\n");
  EXPECT_NE(errors.find("keys.lua:7: run.assessment: alpha must be in (0, 1] or -1"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("keys.lua:10: run.assessment: sections[2]"), std::string::npos) << errors;
}

TEST(SourcePositions, TableBuiltInCodeKeepsTheBlockLine) {
  const std::string errors = errorsOf("code.lua",
                                      "track { segments = { tangent { length = 100 } } }\n"
                                      "local a = {}\n"
                                      "a.alpha = 5\n"
                                      "run {\n"
                                      "  duration = 0.1,\n"
                                      "  assessment = a,\n"
                                      "}\n");
  // `assessment = a` is written at line 6; the key set in code has no line of its own.
  EXPECT_NE(errors.find("code.lua:6: run.assessment: alpha must be in (0, 1] or -1"),
            std::string::npos)
      << errors;
}
