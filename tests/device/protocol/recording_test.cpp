// tests/device/protocol/recording_test.cpp: recording a session and dumping it to text, against a
// golden dump (regenerate with TP_UPDATE_GOLDEN=1 after a deliberate protocol change).
#include "device/protocol/recording.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "device/firmware/controller.h"
#include "device/firmware/firmware_transport.h"
#include "device/protocol/describe.h"
#include "device/protocol/host_link.h"
#include "tests/support/paths.h"

namespace tp::device {
namespace {

using std::chrono::milliseconds;

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Recording, DumpOfAShortJobMatchesGolden) {
  const auto dir = test::scratch_dir("recording");
  const auto file = dir / "link.tpwire";
  {
    PrinterModel m;
    m.nozzles_per_ink = 8;
    PrinterController printer(m, nullptr);
    FirmwareTransport inner(printer);
    auto rec = RecordingTransport::create(inner, file);
    ASSERT_TRUE(rec);
    HostLink link(**rec);
    ASSERT_TRUE(link.handshake());
    ASSERT_TRUE(link.send_msg(MessageType::kJobBegin, JobBeginMsg{3, "golden", 0, 96}));
    ASSERT_TRUE(link.send_msg(MessageType::kCutterCue, CutterCueMsg{1, CueKind::kNotch, 0, 2000}));
    Swath s;
    s.header.rows = 8;
    s.header.width_px = 16;
    s.header.channels = 4;
    s.header.raw_bytes = static_cast<std::uint32_t>(swath_raw_bytes(s.header));
    s.data.assign(s.header.raw_bytes, 0x40);
    ASSERT_TRUE(link.send_swath(s));
    ASSERT_TRUE(link.drain(milliseconds(2000)));
    auto st = link.query_status(milliseconds(2000));
    ASSERT_TRUE(st);
    ASSERT_EQ(st->cue_waiting, 1u);
    ASSERT_TRUE(link.send_msg(MessageType::kCueDone, CueDoneMsg{1}));
    ASSERT_TRUE(link.send_msg(MessageType::kJobEnd, JobEndMsg{1, 340}));
    ASSERT_TRUE(link.drain(milliseconds(2000)));
    ASSERT_TRUE(link.query_status(milliseconds(2000)));
  }
  auto records = read_recording(file);
  ASSERT_TRUE(records) << records.error().message;
  const std::string dump = dump_recording(*records);
  const auto golden = test::source_dir() / "tests/device/protocol/golden/short_job.txt";
  if (std::getenv("TP_UPDATE_GOLDEN")) std::ofstream(golden) << dump;
  EXPECT_EQ(dump, slurp(golden)) << "dump:\n" << dump;
  // The dump names what matters in each direction.
  EXPECT_NE(dump.find("H>P hello #0"), std::string::npos);
  EXPECT_NE(dump.find("P>H identify"), std::string::npos);
  EXPECT_NE(dump.find("state=waiting_for_cue"), std::string::npos);
  EXPECT_NE(dump.find("P>H job_report"), std::string::npos);
}

TEST(Recording, TruncatedRecordingNamesFileAndRecord) {
  const auto dir = test::scratch_dir("recording-bad");
  const auto file = dir / "cut.tpwire";
  std::ofstream(file, std::ios::binary) << "TPWIRE01" << '\x00' << std::string(8, '\0') << '\x10' << '\0' << '\0'
                                        << '\0' << "short";
  auto r = read_recording(file);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find(file.string()), std::string::npos);
  EXPECT_NE(r.error().message.find("record 1"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("16 bytes"), std::string::npos) << r.error().message;

  std::ofstream(dir / "not.tpwire") << "hello";
  auto n = read_recording(dir / "not.tpwire");
  ASSERT_FALSE(n);
  EXPECT_NE(n.error().message.find("not a wire recording"), std::string::npos);
}

TEST(Recording, DumpShowsCorruptFramesAndEvents) {
  std::vector<std::uint8_t> good, bad;
  ASSERT_TRUE(encode_frame(MessageType::kStatusQuery, 5, {}, good));
  std::vector<std::uint8_t> payload(8, 1);
  ASSERT_TRUE(encode_frame(MessageType::kSwathData, 6, payload, bad));
  bad[20] ^= 0xFF;
  std::vector<WireRecord> recs{{RecordKind::kHostToPrinter, 0, good},
                               {RecordKind::kEvent, 10, {'r', 'e', 's', 'e', 't'}},
                               {RecordKind::kHostToPrinter, 20, bad}};
  const std::string dump = dump_recording(recs, DumpOptions{true});
  EXPECT_EQ(dump,
            "0.000000 H>P status_query #5\n"
            "0.000010 --- reset\n"
            "0.000020 H>P error: frame seq 6 (swath_data, 8 bytes): payload CRC mismatch\n");
}

}  // namespace
}  // namespace tp::device
