#pragma once
// A track store: a folder of files <track hash>.h5, each holding one /track group exactly as a
// result file holds it (track_output.hpp), plus the attribute /track/track_hash. Results that
// share a track (the cases of a study) reference one store file instead of each repeating it:
// their /track keeps only attributes, `stored_in` (the store file's path relative to the
// result's folder), `track_hash` and the small attributes of /track (length, step, gauge, ...).
//
// A store file is written under a unique temporary name and renamed into place (ResultFile), so
// runs writing the same track at once never expose a partial file: the last rename leaves one
// complete file. An existing file is reused when it opens and its track_hash attribute equals
// the hash of the track wanted; otherwise it is replaced.
#include <string>

#include "workbench/io/result_file.hpp"
#include "workbench/io/track_output.hpp"

namespace rb::io {

struct StoredTrack {
  std::string file;      // DIR/<hash>.h5
  std::string hash;      // trackHash of the content
  bool written = false;  // false: an existing store file was reused
};

// The store file of `c` in `dir` (created with its parents), written when it is missing or does
// not carry the hash. Throws WriteError.
StoredTrack storeTrack(const TrackContent& c, const std::string& dir);

// Whether `file` is a store file of the track with hash `hash` (it opens, its /track/track_hash
// equals `hash`, it has a centreline).
bool isStoredTrack(const std::string& file, const std::string& hash);

// The reference in the result `f`: /track with stored_in (relative to the folder of f.path()),
// track_hash and the /track attributes of `c`.
void writeTrackReference(ResultFile& f, const TrackContent& c, const StoredTrack& s);

}  // namespace rb::io
