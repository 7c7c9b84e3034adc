// host/app/printctl/bench_garment_corpus.h: the patterns of a corpus folder, each with the body to sew it on.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "geometry/body/body_sdf.h"
#include "host/common/error.h"

namespace tp::host::cli {

/// One pattern of a corpus and its body (shared between patterns on the same body).
struct CorpusEntry {
  std::string name;                  ///< file stem
  std::filesystem::path pattern;
  std::shared_ptr<const geometry::BodySdf> body;
  std::string body_name;             ///< "dress_form cisFemaleAdult34", the OBJ's path, ...
  std::string error;                 ///< why no body was found (then body is null)
};

/// Every pattern file (.json, .svg, .dxf; not *.body.json) of `dir`, sorted by name, with its body:
/// a sidecar `<stem>.body.json` ({"mesh": path, "units": "m"}, {"freesewing": 34} or
/// {"size": "M"}); else a FreeSewing name's size (`-cisFemaleAdult34`) as a dress form; else the
/// folder's only .obj; else `../bodies/mean_female.obj` (GarmentCode's layout). An OBJ without
/// stated units whose extent is under 10 units is in metres, else mm. Fails (kIo) when the
/// folder cannot be read; a pattern without a body carries the reason in `error`.
[[nodiscard]] Result<std::vector<CorpusEntry>> corpus_entries(const std::filesystem::path& dir);

}  // namespace tp::host::cli
