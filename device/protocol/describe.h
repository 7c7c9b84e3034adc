// device/protocol/describe.h: one line of text per frame or recording, for logs, wire dumps and
// golden tests.
#pragma once

#include <string>
#include <vector>

#include "device/protocol/frame.h"
#include "device/protocol/recording.h"

namespace tp::device {

/// "swath_header #5 swath=0 pass=0 dir=ltr first_row=0 rows=64 ..." — the message's fields, or
/// "<type> #<seq> malformed: <reason>" if its payload does not decode.
std::string describe_frame(const Frame& frame);

struct DumpOptions {
  bool times = false;  ///< prefix each line with the record's time in seconds
};

/// Decodes a recording into text: each direction's bytes go through its own frame decoder;
/// lines are "H>P ..." (host to printer), "P>H ...", "--- event" and "H>P error: ..." for
/// corrupt frames. Byte-identical for identical traffic, so it can be diffed against goldens.
std::string dump_recording(const std::vector<WireRecord>& records, const DumpOptions& options = {});

}  // namespace tp::device
