#include <gtest/gtest.h>

#include "workbench/core/error.hpp"

TEST(Diagnostics, CollectsAllAndFormatsFileLine) {
  rb::Diagnostics d;
  d.add({"a.lua", 3}, "first");
  d.add({"<command line>", 0}, "second");
  try {
    d.throwIfAny();
    FAIL() << "expected InputError";
  } catch (const rb::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "a.lua:3: first\n<command line>: second");
    EXPECT_EQ(e.diagnostics().size(), 2u);
  }
}

TEST(Check, ThrowsLogicError) {
  EXPECT_THROW(RB_CHECK(1 == 2, "bad"), std::logic_error);
}
