// Writes the seed inputs of the `tables` harness: a small S1002 / 60E1 LUT and KEC table saved in
// the cache format, each as a whole file (mode byte 0 / 1) and as a bare payload (mode byte 2 / 3;
// the harness wraps it in a valid header and checksum). Usage: fuzz_make_table_seeds OUT_DIR
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "workbench/contact/config.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"
#include "workbench/contact/table_io.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/rail60e1.hpp"
#include "workbench/profiles/s1002.hpp"

namespace {

namespace fs = std::filesystem;
using rb::profiles::Profile;
using rb::profiles::Side;

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeSeeds(const fs::path& out, const std::string& name, char kecBit,
                const std::string& file) {
  constexpr std::size_t header = 16 + 4 * 8, checksum = 8;
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
  const double r0 = 0.46;
  const auto pos = rb::profiles::positionS1002On60E1(1.360, 1.435, r0, 1.0 / 40.0);
  rb::contact::ContactGeometryConfig c;
  c.left_wheel = std::make_shared<const Profile>(rb::profiles::s1002Wheel(r0, Side::Left));
  c.right_wheel = std::make_shared<const Profile>(rb::profiles::s1002Wheel(r0, Side::Right));
  c.left_rail = std::make_shared<const Profile>(rb::profiles::rail60E1(Side::Left));
  c.right_rail = std::make_shared<const Profile>(rb::profiles::rail60E1(Side::Right));
  c.wheel_lw = pos.Lw;
  c.rail_lr = pos.Lr;
  c.beta = pos.beta;
  c.r0 = r0;
  // Coarse grids keep the seeds a few kilobytes.
  c.lut_y = {-0.008, 0.008, 2e-3};
  c.lut_gauge = {-1e-3, 1e-3, 1e-3};
  c.kec_s = {-0.012, 0.012, 1e-3};
  const fs::path tmp = out / "tmp.table";
  rb::contact::saveTable(rb::contact::buildLut(c), tmp.string());
  writeSeeds(out, "lut", 0, readBytes(tmp.string()));
  rb::contact::saveTable(rb::contact::buildKec(c), tmp.string());
  writeSeeds(out, "kec", 1, readBytes(tmp.string()));
  fs::remove(tmp);
  return 0;
}
