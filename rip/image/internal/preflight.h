// rip/image/internal/preflight.h: checks an image file's container before any decoder library sees
// it: which format it is (by content, not by name) and whether its embedded ICC profile is sound.
//
// Design images come from outside the print room. OpenImageIO 2.4 (Debian 12) parses embedded ICC
// profiles without bounds checks (a profile whose tag claims fewer bytes than its type needs makes
// it copy gigabytes), and when the reader chosen by the file name fails it tries every other format
// plugin it has. So the container is walked here first: only PNG, JPEG, TIFF (and BigTIFF) and
// OpenEXR are accepted; the ICC profile of the first three is found and validated against the
// ICC specification's structure (header, tag table, the tag types that get decoded), and so are the
// IPTC records OpenImageIO walks without bounds (JPEG APP13, TIFF tag 33723).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include <OpenImageIO/filesystem.h>

#include "rip/common/error.h"

namespace tp::rip {

/// Image container formats accepted for design images and textures.
enum class ImageFormat { kPng, kJpeg, kTiff, kOpenExr };

/// OpenImageIO's name of the format's reader ("png", "jpeg", "tiff", "openexr").
std::string_view oiio_format_name(ImageFormat format);

/// Sniffs the format from the first bytes and validates the embedded ICC profile, if any.
/// Fails (kImage) naming `name`: unreadable, not one of the accepted formats, a malformed,
/// truncated or incomplete embedded profile (what is wrong, which tag), or IPTC records that run
/// past their block.
[[nodiscard]] Result<ImageFormat> preflight_image(const std::string& name, OIIO_NAMESPACE::Filesystem::IOProxy& io);

/// Structural check of an ICC profile: header size and signature, tag table inside the profile,
/// every tag inside the profile and long enough for its type ('text', 'desc', 'mluc' records).
/// Fails (kImage) with a message that starts with "embedded ICC profile".
[[nodiscard]] Status check_icc_profile(std::span<const std::uint8_t> icc);

}  // namespace tp::rip
