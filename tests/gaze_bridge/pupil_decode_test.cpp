#include "pupil_decode.h"

#include <gtest/gtest.h>

#include <msgpack.hpp>

#include "emulators.h"

using gaze_bridge::decodePupilSurfaceMessage;
using gaze_bridge::TrackerSample;
using gaze_bridge_test::packSurfaceMessage;
using gaze_bridge_test::PupilGaze;

TEST(PupilDecode, DecodesEverySampleAndFlipsY) {
  const std::string payload = packSurfaceMessage(
      "screen", {{0.25, 0.75, 0.95, true, 100.0}, {0.5, 0.1, 0.3, true, 100.004}, {1.3, 0.5, 0.99, false, 100.008}});
  std::vector<TrackerSample> out;
  std::size_t skipped = 0;
  ASSERT_EQ(decodePupilSurfaceMessage(payload.data(), payload.size(), 77, out, skipped), "");
  EXPECT_EQ(skipped, 0u);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_DOUBLE_EQ(out[0].x, 0.25);
  EXPECT_DOUBLE_EQ(out[0].y, 0.25);  // 1 - 0.75
  EXPECT_FLOAT_EQ(out[0].confidence, 0.95f);
  EXPECT_TRUE(out[0].valid);
  EXPECT_EQ(out[0].tracker_time_s, 100.0);
  EXPECT_EQ(out[0].arrival_ns, 77);
  EXPECT_DOUBLE_EQ(out[1].y, 0.9);
  EXPECT_FLOAT_EQ(out[1].confidence, 0.3f);
  EXPECT_FALSE(out[2].valid);  // off the surface
}

TEST(PupilDecode, AcceptsIntegerAndFloat32Numbers) {
  msgpack::sbuffer buffer;
  msgpack::packer<msgpack::sbuffer> pk(&buffer);
  pk.pack_map(1);
  pk.pack(std::string("gaze_on_surfaces"));
  pk.pack_array(1);
  pk.pack_map(4);
  pk.pack(std::string("norm_pos"));
  pk.pack_array(2);
  pk.pack(1);      // integer
  pk.pack(0.25f);  // float32
  pk.pack(std::string("confidence"));
  pk.pack(1);
  pk.pack(std::string("on_surf"));
  pk.pack(true);
  pk.pack(std::string("timestamp"));
  pk.pack(3);
  std::vector<TrackerSample> out;
  std::size_t skipped = 0;
  ASSERT_EQ(decodePupilSurfaceMessage(buffer.data(), buffer.size(), 0, out, skipped), "");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].x, 1.0);
  EXPECT_EQ(out[0].y, 0.75);
}

TEST(PupilDecode, RejectsGarbageAndSkipsBadEntries) {
  std::vector<TrackerSample> out;
  std::size_t skipped = 0;
  const std::string garbage = "\xc1\xff not msgpack";
  EXPECT_NE(decodePupilSurfaceMessage(garbage.data(), garbage.size(), 0, out, skipped), "");
  msgpack::sbuffer buffer;
  msgpack::packer<msgpack::sbuffer> pk(&buffer);
  pk.pack_array(2);
  pk.pack(1);
  pk.pack(2);
  EXPECT_EQ(decodePupilSurfaceMessage(buffer.data(), buffer.size(), 0, out, skipped), "payload is not a msgpack map");
  buffer.clear();
  pk.pack_map(1);
  pk.pack(std::string("name"));
  pk.pack(std::string("screen"));
  EXPECT_EQ(decodePupilSurfaceMessage(buffer.data(), buffer.size(), 0, out, skipped), "no gaze_on_surfaces");
  // One good entry and one with a three-element norm_pos and one with a string confidence.
  buffer.clear();
  pk.pack_map(1);
  pk.pack(std::string("gaze_on_surfaces"));
  pk.pack_array(3);
  for (int variant = 0; variant < 3; ++variant) {
    pk.pack_map(3);
    pk.pack(std::string("norm_pos"));
    pk.pack_array(variant == 1 ? 3 : 2);
    for (int k = 0; k < (variant == 1 ? 3 : 2); ++k) pk.pack(0.5);
    pk.pack(std::string("confidence"));
    if (variant == 2) {
      pk.pack(std::string("high"));
    } else {
      pk.pack(0.9);
    }
    pk.pack(std::string("timestamp"));
    pk.pack(1.0);
  }
  EXPECT_EQ(decodePupilSurfaceMessage(buffer.data(), buffer.size(), 0, out, skipped), "");
  EXPECT_EQ(out.size(), 1u);
  EXPECT_EQ(skipped, 2u);
  EXPECT_TRUE(out[0].valid);  // on_surf missing: taken as on the surface
}

TEST(PupilDecode, TruncatedPayloadIsRejected) {
  const std::string payload = packSurfaceMessage("screen", {{0.25, 0.75, 0.95, true, 100.0}});
  std::vector<TrackerSample> out;
  std::size_t skipped = 0;
  for (std::size_t cut = 0; cut < payload.size(); ++cut) {
    EXPECT_NE(decodePupilSurfaceMessage(payload.data(), cut, 0, out, skipped), "") << cut;
  }
  EXPECT_TRUE(out.empty());
}

TEST(PupilDecode, ConfidenceOutsideZeroToOneSkipsTheEntry) {
  // Found by tests/fuzz/fuzz_pupil_decode: a confidence of -2.9e238 passed as finite, then its cast to
  // float was undefined behaviour (and gave -inf). Pupil's confidence lies in [0, 1].
  const std::string payload = packSurfaceMessage("screen", {{0.25, 0.75, -2.9e238, true, 1.0},
                                                            {0.25, 0.75, 1e300, true, 2.0},
                                                            {0.25, 0.75, 1.5, true, 3.0},
                                                            {0.25, 0.75, -0.1, true, 4.0},
                                                            {0.5, 0.5, 1.0, true, 5.0},
                                                            {0.5, 0.5, 0.0, true, 6.0}});
  std::vector<TrackerSample> out;
  std::size_t skipped = 0;
  ASSERT_EQ(decodePupilSurfaceMessage(payload.data(), payload.size(), 0, out, skipped), "");
  EXPECT_EQ(skipped, 4u);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].confidence, 1.0f);
  EXPECT_EQ(out[1].confidence, 0.0f);
}
