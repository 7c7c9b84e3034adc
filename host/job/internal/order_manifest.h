// host/job/internal/order_manifest.h: reading job.json's "order" (sizes, placement, copies).
#pragma once

#include "host/job/internal/field_reader.h"
#include "host/job/job.h"
#include "host/job/package.h"

namespace tp::host::internal {

/// Reads `order` into `job.order` and checks it against the job's garment and text layers
/// (problems name the size, the file and the JSON pointer).
void read_order(FieldReader o, const JobPackage* pkg, Job& job);

/// Text layers whose template takes fields from copies need an order with those fields.
void check_text_layers(const Job& job, Problems& problems);

}  // namespace tp::host::internal

namespace tp::host::internal {

/// Resolves an asset field of the package into `out` (unsafe or missing files are problems).
void read_asset(FieldReader& r, const std::string& key, bool required, const JobPackage* pkg,
                std::optional<std::filesystem::path>& out);

}  // namespace tp::host::internal
