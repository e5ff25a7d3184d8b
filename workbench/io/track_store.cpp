#include "workbench/io/track_store.hpp"

#include <cstring>
#include <filesystem>
#include <system_error>

#include "workbench/io/result_reader.hpp"

namespace fs = std::filesystem;

namespace rb::io {

bool isStoredTrack(const std::string& file, const std::string& hash) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return false;
  const ResultReader r(file);
  return r.ok() && r.text("/track", "track_hash") == hash && r.has("/track/centreline/s");
}

namespace {

// Every dataset of the store equals the content in hand, value for value (bit for bit): a store
// file is only reused when it holds exactly this track, whatever its hash attribute says.
bool holds(const std::string& file, const TrackContent& c) {
  const ResultReader r(file);
  if (!r.ok()) return false;
  for (const auto& item : c.items) {
    const auto* d = std::get_if<TrackContent::Dataset>(&item);
    if (!d) continue;
    const auto stored = r.dataset(d->path);
    if (!stored || stored->size() != d->data.size() ||
        (!d->data.empty() &&
         std::memcmp(stored->data(), d->data.data(), d->data.size() * sizeof(double)) != 0))
      return false;
  }
  return true;
}

}  // namespace

StoredTrack storeTrack(const TrackContent& c, const std::string& dir) {
  StoredTrack s;
  s.hash = trackHash(c);
  s.file = (fs::path(dir) / (s.hash + ".h5")).string();
  if (isStoredTrack(s.file, s.hash) && holds(s.file, c)) return s;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw WriteError("cannot create the track store '" + dir + "': " + ec.message());
  ResultFile f(s.file);
  f.attr("/", "content", std::string("railbench track store: one /track group"));
  writeTrackContent(f, c);
  f.attr("/track", "track_hash", s.hash);
  f.finalize();
  s.written = true;
  return s;
}

void writeTrackReference(ResultFile& f, const TrackContent& c, const StoredTrack& s) {
  // Both sides resolved (symlinks included) so the relative path holds from the result's folder.
  const fs::path folder = fs::weakly_canonical(fs::absolute(f.path()).parent_path());
  const fs::path store = fs::weakly_canonical(fs::absolute(s.file));
  f.attr("/track", "stored_in", store.lexically_relative(folder).string());
  f.attr("/track", "track_hash", s.hash);
  for (const auto& a : trackGroupAttrs(c))
    std::visit([&](const auto& v) { f.attr(a.group, a.name, v); }, a.value);
}

}  // namespace rb::io
