// rip/colour/internal/lcms_handles.h: owning handles for lcms2 profiles and transforms.
#pragma once

#include <memory>

#include <lcms2.h>

namespace tp::rip::lcms {

struct ProfileCloser {
  void operator()(void* p) const { if (p) cmsCloseProfile(p); }
};
struct TransformDeleter {
  void operator()(void* t) const { if (t) cmsDeleteTransform(t); }
};

/// An owned cmsHPROFILE.
using Profile = std::unique_ptr<void, ProfileCloser>;
/// An owned cmsHTRANSFORM.
using Transform = std::unique_ptr<void, TransformDeleter>;

/// Routes lcms2's error reports to the rip logger instead of stderr (installed once, idempotent).
void install_error_handler();

}  // namespace tp::rip::lcms
