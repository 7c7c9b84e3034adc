// tests/support/paths.h: where tests find the source tree, the shared reference data and binaries.
#pragma once

#include <filesystem>
#include <string>

namespace tp::test {

/// ../shared/data beside the checkout (TP_SHARED_DATA overrides).
std::filesystem::path shared_data_dir();
/// The project's source root (TP_SOURCE_DIR overrides).
std::filesystem::path source_dir();
/// build/bin, where printctl, printd and printsim land (TP_BIN_DIR overrides).
std::filesystem::path bin_dir();
/// A fresh empty directory for one test, removed and recreated on each call with the same name.
std::filesystem::path scratch_dir(const std::string& name);

}  // namespace tp::test
