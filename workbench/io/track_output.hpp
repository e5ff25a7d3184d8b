#pragma once
// /track in the result file (architecture.md, "Output layout"): centreline, segments and, when the
// scene has them, irregularities and their target PSD.
//
// The group is first assembled as TrackContent, the ordered list of its attributes and datasets,
// so that the same content can be written into a result file, hashed, or written once into a
// track store file that many results reference (track_store.hpp).
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "workbench/io/result_file.hpp"
#include "workbench/io/schema.hpp"
#include "workbench/track/samples.hpp"
#include "workbench/track/spec.hpp"

namespace rb::io {

struct TrackContent {
  struct Attr {
    std::string group, name;
    std::variant<std::string, double, std::int64_t> value;
  };
  struct Dataset {
    std::string path, units;
    std::vector<double> data;
    // For /schema (not hashed: they describe the data, they are not part of it).
    std::string meaning, codes;
  };
  // In the order they are written: the order fixes the file's layout.
  std::vector<std::variant<Attr, Dataset>> items;
};

TrackContent trackContent(const track::TrackSpec& spec, const track::TrackSamples& t);
// Writes every item of `c` into `f`, in order.
void writeTrackContent(ResultFile& f, const TrackContent& c);
// The attributes of /track itself (length, step, gauge, ...): what a reference to a stored track
// keeps in the result.
std::vector<TrackContent::Attr> trackGroupAttrs(const TrackContent& c);
// The /schema rows of the datasets of `c` and the codes of its code-valued datasets (segment kind
// and side), for writeSchema.
std::vector<SchemaEntry> trackSchema(const TrackContent& c);
std::vector<std::pair<std::string, std::string>> trackEnums();
// FNV-1a 128 over every item (kind, names, units, attribute values, dataset lengths and the
// IEEE-754 bytes of every value) as 32 hex digits: equal hashes mean equal datasets and
// attributes, in the same order.
std::string trackHash(const TrackContent& c);

}  // namespace rb::io
