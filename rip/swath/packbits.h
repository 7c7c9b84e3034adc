// rip/swath/packbits.h: forwards to the one PackBits codec in device/swath/packbits.h, for the TIFF
// band writer until it moves to libtiff; new code includes the device header.
#pragma once

#include "device/swath/packbits.h"

namespace tp::rip {

using device::packbits_encode;
using device::packbits_max_size;

}  // namespace tp::rip
