// libFuzzer harness: see entry_points.hpp and tests/fuzz/README.md.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "entry_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rb::fuzz::resultFiles(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
