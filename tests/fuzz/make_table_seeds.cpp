// Writes the seed inputs of the `tables` harness: a small S1002 / 60E1 LUT and KEC table saved in
// the cache format, each as a whole file (mode byte 0 / 1) and as a bare payload (mode byte 2 / 3;
// the harness wraps it in a valid header and checksum). Usage: fuzz_make_table_seeds OUT_DIR
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "entry_points.hpp"
#include "workbench/contact/config.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"
#include "workbench/contact/table_io.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/rail60e1.hpp"
#include "workbench/profiles/s1002.hpp"

namespace {

namespace fs = std::filesystem;

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeSeeds(const fs::path& out, const std::string& name, char kecBit,
                const std::string& file) {
  // Header: magic (16), byte-order mark, format and algorithm versions (3 x 8), key size (8) and
  // key, payload size (8); then the payload and an 8-byte checksum.
  std::uint64_t key_size = 0;
  std::memcpy(&key_size, file.data() + 16 + 24, 8);
  const std::size_t header = 16 + 24 + 8 + key_size + 8, checksum = 8;
  std::ofstream whole(out / (name + "_file"), std::ios::binary | std::ios::trunc);
  whole.put(kecBit);
  whole << file;
  std::ofstream payload(out / (name + "_payload"), std::ios::binary | std::ios::trunc);
  payload.put(static_cast<char>(kecBit | 2));
  payload << file.substr(header, file.size() - header - checksum);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
    return 2;
  }
  const fs::path out = argv[1];
  fs::create_directories(out);
  const rb::contact::ContactGeometryConfig& c = rb::fuzz::seedTableConfig();
  const fs::path tmp = out / "tmp.table";
  rb::contact::saveTable(rb::contact::buildLut(c), c, tmp.string());
  writeSeeds(out, "lut", 0, readBytes(tmp.string()));
  rb::contact::saveTable(rb::contact::buildKec(c), c, tmp.string());
  writeSeeds(out, "kec", 1, readBytes(tmp.string()));
  fs::remove(tmp);
  return 0;
}
