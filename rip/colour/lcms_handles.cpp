// rip/colour/lcms_handles.cpp: sends lcms2's error reports to the rip logger.
#include "rip/colour/internal/lcms_handles.h"

#include <mutex>

#include "rip/common/internal/log.h"

namespace tp::rip::lcms {

namespace {
void log_lcms_error(cmsContext, cmsUInt32Number code, const char* text) {
  // lcms2 reports problems here and then returns a null handle; the caller turns that into an
  // Error naming the file, so this is debug detail only.
  logger().debug("lcms2 error {}: {}", code, text ? text : "");
}
}  // namespace

void install_error_handler() {
  static std::once_flag once;
  std::call_once(once, [] { cmsSetLogErrorHandler(log_lcms_error); });
}

}  // namespace tp::rip::lcms
