// The viewer against the real sph_server on what the foveation does: a short blind study driven
// with XTest key presses (its CSV and summary), a bad study refused before anything changes, the
// panel's figures and the server's rings read back from a snapshot, and the server's one warning
// when its real-time governor is held at the ceiling.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <thread>
#include <zmq.hpp>

#include "binomial_stats.h"
#include "decoded_frame.h"
#include "study_plan.h"
#include "study_trials.h"
#include "support/server_program.h"
#include "viewer_process.h"
#include "x11_input.h"

using namespace viewer_test;
using namespace std::chrono_literals;

namespace {

constexpr auto kWait = 90s;

std::vector<std::string> serverArgs(const std::string& preset, const std::string& method,
                                    std::vector<std::string> extra = {}) {
  std::vector<std::string> args{
      SPH_SERVER_PATH, "--scene", "tiny_pool", "--scene-dir", SPH_NET_TEST_SCENE_DIR, "--threads", "1",
      "--preset",      preset,    "--method",  method,        "--status-interval",    "0"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

std::vector<std::string> endpointArgs(const sph_test::ServerEndpoints& e) {
  return {"--frames-endpoint", e.frames, "--gaze-endpoint",    e.gaze,
          "--pose-endpoint",   e.pose,   "--control-endpoint", e.control};
}

std::vector<std::string> join(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

template <typename Condition>
bool waitUntil(Condition condition, std::chrono::seconds limit = kWait) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    if (condition()) return true;
    std::this_thread::sleep_for(50ms);
  }
  return condition();
}

std::vector<std::vector<std::string>> readCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(readFile(path));
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> row;
    std::istringstream fields(line);
    std::string f;
    while (std::getline(fields, f, ',')) row.push_back(f);
    rows.push_back(row);
  }
  return rows;
}

// The newest frame the server publishes that satisfies `predicate`.
template <typename Predicate>
bool nextFrame(const std::string& endpoint, Predicate predicate, gsph::v1::Frame& out) {
  zmq::context_t context;
  zmq::socket_t sub(context, zmq::socket_type::sub);
  sub.set(zmq::sockopt::conflate, 1);
  sub.set(zmq::sockopt::linger, 0);
  sub.set(zmq::sockopt::subscribe, "");
  sub.connect(endpoint);
  return waitUntil([&] {
    zmq::message_t m;
    if (!sub.recv(m, zmq::recv_flags::dontwait)) return false;
    return out.ParseFromArray(m.data(), static_cast<int>(m.size())) && predicate(out);
  });
}

gsph::v1::ControlReply control(const std::string& endpoint, gsph::v1::Control request) {
  zmq::context_t context;
  zmq::socket_t dealer(context, zmq::socket_type::dealer);
  dealer.set(zmq::sockopt::linger, 0);
  dealer.set(zmq::sockopt::rcvtimeo, 30000);
  dealer.connect(endpoint);
  request.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
  request.set_request_id(1);
  const std::string bytes = request.SerializeAsString();
  dealer.send(zmq::buffer(bytes), zmq::send_flags::none);
  zmq::message_t m;
  gsph::v1::ControlReply reply;
  if (dealer.recv(m)) reply.ParseFromArray(m.data(), static_cast<int>(m.size()));
  return reply;
}

const char* kStudy = R"({
  "name": "window_test", "question": "two_interval", "scenes": ["tiny_pool"],
  "comparisons": [{"name": "gaze_vs_regular", "reference": {"method": "regular"},
                   "test": {"method": "gaze", "parameters": {"gaze_radius": 0.03}}}],
  "interval_s": 2, "blank_s": 0.3, "repetitions": 2, "seed": 11})";

TEST(ViewerStudy, AShortStudyRunsAgainstTheServerAndWritesItsResults) {
  const std::string dir = scratchDir();
  std::ofstream(dir + "/study.json") << kStudy;
  sph_test::ServerProgram server(serverArgs("thesis", "gaze"), dir + "/server");
  auto viewer = startViewer(join(endpointArgs(server.endpoints()),
                                 {"--study", dir + "/study.json", "--study-out", dir + "/out.csv", "--viewer-id",
                                  "study", "--width", "480", "--height", "270", "--gaze-at", "0.4", "0.6"}),
                            dir + "/viewer.log");
  X11Input x11;
  const int answers[] = {1, 2};
  for (int trial = 1; trial <= 2; ++trial) {
    const std::string asking = "trial " + std::to_string(trial) + " of 2: waiting for the answer";
    ASSERT_TRUE(waitUntil([&] { return readFile(dir + "/viewer.log").find(asking) != std::string::npos; }))
        << readFile(dir + "/viewer.log") << server.log();
    ASSERT_TRUE(waitUntil([&] { return x11.windowOrigin("sph_viewer study").has_value(); }));
    x11.focus("sph_viewer study");
    x11.key(answers[trial - 1] == 1 ? "1" : "2");
    if (trial == 1) {
      ASSERT_TRUE(waitUntil([&] { return readCsv(dir + "/out.csv").size() == 2; })) << readFile(dir + "/viewer.log");
    }
  }
  const auto code = viewer->waitExit(kWait);
  ASSERT_TRUE(code.has_value()) << readFile(dir + "/viewer.log");
  ASSERT_EQ(*code, 0) << readFile(dir + "/viewer.log");

  const auto rows = readCsv(dir + "/out.csv");
  ASSERT_EQ(rows.size(), 3u) << readFile(dir + "/out.csv");
  const std::vector<std::string>& header = rows[0];
  const auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << name;
    return static_cast<std::size_t>(it - header.begin());
  };
  const viewer::StudyPlan plan = viewer::parseStudyPlan(kStudy, "study");
  const auto trials = viewer::makeTrials(plan, 11);
  int correct = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    ASSERT_EQ(row.size(), header.size());
    EXPECT_EQ(row[column("trial")], std::to_string(i));
    EXPECT_EQ(row[column("seed")], "11");
    EXPECT_EQ(row[column("scene")], "tiny_pool");
    EXPECT_EQ(row[column("order")], viewer::orderText(trials[i - 1])) << "the order the seed gives";
    EXPECT_EQ(row[column("answer")], std::to_string(answers[i - 1]));
    const bool right = viewer::answerCorrect(plan.question, trials[i - 1], answers[i - 1]);
    EXPECT_EQ(row[column("correct")], right ? "1" : "0");
    correct += right;
    EXPECT_GT(std::stod(row[column("response_s")]), 0.0);
    EXPECT_GT(std::stoi(row[column("gaze_frames")]), 0);
    // The gaze this viewer sent (--gaze-at) is the gaze the gaze method's steps used; the regular
    // interval's frames use none.
    const double share = std::stod(row[column("gaze_tracking_share")]);
    EXPECT_GT(share, 0.0);
    EXPECT_LT(share, 1.0);
    EXPECT_NEAR(std::stod(row[column("gaze_mean_x")]), 0.4, 1e-3);
    EXPECT_NEAR(std::stod(row[column("gaze_mean_y")]), 0.6, 1e-3);
    EXPECT_GT(std::stod(row[column("realtime_ratio_1")]), 0.0);
    EXPECT_GT(std::stod(row[column("realtime_ratio_2")]), 0.0);
  }
  const auto summary = readCsv(dir + "/out.summary.csv");
  ASSERT_EQ(summary.size(), 2u) << readFile(dir + "/out.summary.csv");
  EXPECT_EQ(summary[1][3], "gaze_vs_regular");
  EXPECT_EQ(summary[1][4], "2");
  EXPECT_EQ(summary[1][5], std::to_string(correct));
  const viewer::Interval ci = viewer::wilsonInterval95(correct, 2);
  EXPECT_NEAR(std::stod(summary[1][7]), ci.low, 1e-4);
  EXPECT_NEAR(std::stod(summary[1][8]), ci.high, 1e-4);
  EXPECT_NEAR(std::stod(summary[1][9]), viewer::binomialTestP(correct, 2, 0.5), 1e-5);
  // The server switched to each trial's reference (regular) and back to the test (gaze).
  EXPECT_GE(count(server.log(), "-> regular"), 2u) << server.log();
  EXPECT_GE(count(server.log(), "-> gaze"), 1u) << server.log();
}

TEST(ViewerStudy, BadStudiesAreRefusedBeforeAnythingChanges) {
  const std::string dir = scratchDir();
  std::ofstream(dir + "/bad.json") << R"({"name": "x", "scenes": ["tiny_pool"], "comparisons": [
      {"reference": {"method": "regular"}, "test": {"method": "sharper"}}]})";
  auto refused = startViewer({"--study", dir + "/bad.json"}, dir + "/bad.log");
  const auto bad_code = refused->waitExit(kWait);
  ASSERT_TRUE(bad_code.has_value());
  EXPECT_EQ(*bad_code, 2);
  EXPECT_NE(readFile(dir + "/bad.log").find("unknown method \"sharper\""), std::string::npos)
      << readFile(dir + "/bad.log");

  // A scene the server lacks: exit 5, and the server was asked nothing but its status.
  std::ofstream(dir + "/unknown.json") << R"({"name": "x", "scenes": ["atlantis"], "comparisons": [
      {"reference": {"method": "regular"}, "test": {"method": "surface"}}]})";
  sph_test::ServerProgram server(serverArgs("thesis", "gaze"), dir + "/server");
  auto viewer = startViewer(
      join(endpointArgs(server.endpoints()), {"--study", dir + "/unknown.json", "--study-out", dir + "/out.csv"}),
      dir + "/viewer.log");
  const auto code = viewer->waitExit(kWait);
  ASSERT_TRUE(code.has_value()) << readFile(dir + "/viewer.log");
  EXPECT_EQ(*code, 5) << readFile(dir + "/viewer.log");
  EXPECT_NE(readFile(dir + "/viewer.log").find("the server has no scene \"atlantis\""), std::string::npos);
  // Results that cannot be written: the study does not start (exit 1).
  std::ofstream(dir + "/good.json") << kStudy;
  auto unwritable = startViewer(
      join(endpointArgs(server.endpoints()), {"--study", dir + "/good.json", "--study-out", dir + "/missing/out.csv"}),
      dir + "/unwritable.log");
  const auto unwritable_code = unwritable->waitExit(kWait);
  ASSERT_TRUE(unwritable_code.has_value());
  EXPECT_EQ(*unwritable_code, 1);
  EXPECT_NE(readFile(dir + "/unwritable.log").find("cannot write the study's results to"), std::string::npos)
      << readFile(dir + "/unwritable.log");
  const std::string log = server.log();
  EXPECT_EQ(count(log, "->"), 0u) << log;
  EXPECT_EQ(count(log, "refused"), 0u) << log;
}

TEST(ViewerFoveation, PanelFiguresAndTheServersRingsInASnapshot) {
  const std::string dir = scratchDir();
  // The governor off: the rings stay as the configured gain puts them, so a later frame has them too.
  sph_test::ServerProgram server(serverArgs("pbf", "foveated", {"--realtime", "off"}), dir + "/server");
  constexpr int kW = 640, kH = 360;
  auto viewer = startViewer(join(endpointArgs(server.endpoints()),
                                 {"--snapshot", dir + "/fov.png", "--panel-text", dir + "/panel.txt", "--frames", "40",
                                  "--gaze-at", "0.5", "0.5", "--render", "particles", "--width", std::to_string(kW),
                                  "--height", std::to_string(kH), "--timeout", "120", "--viewer-id", "rings"}),
                            dir + "/viewer.log");
  const auto code = viewer->waitExit(150s);
  ASSERT_TRUE(code.has_value() && *code == 0) << readFile(dir + "/viewer.log");
  const std::string panel = readFile(dir + "/panel.txt");
  EXPECT_NE(panel.find("foveation  q 1.00, g 1.0"), std::string::npos) << panel;
  EXPECT_NE(panel.find("visible over budget"), std::string::npos) << panel;
  EXPECT_NE(panel.find("fovea      "), std::string::npos) << panel;
  EXPECT_NE(panel.find("gaze       tracking"), std::string::npos) << panel;
  EXPECT_NE(panel.find("particles "), std::string::npos) << panel;

  gsph::v1::Frame frame;
  ASSERT_TRUE(nextFrame(
      server.endpoints().frames, [](const gsph::v1::Frame& f) { return f.fovea_ring_radii_size() > 0; }, frame));
  viewer::RgbaImage image;
  std::string error;
  ASSERT_TRUE(viewer::readPng(dir + "/fov.png", image, error)) << error;
  const std::size_t levels = static_cast<std::size_t>(frame.level_radii_size());
  int checked = 0;
  for (int k = 0; k < frame.fovea_ring_radii_size(); ++k) {
    const double r = frame.fovea_ring_radii(k) * kW;
    if (r < 4.0 || r > kH / 2.0 - 4.0) continue;
    // Right of the gaze point and below it, in the ring's level colour.
    const std::size_t level = static_cast<std::size_t>(k) + 1;
    const auto ofLevel = [&](Colour c) { return isLevel(c, level, levels); };
    bool right = false, below = false;
    for (int d = -2; d <= 2; ++d) {
      for (int e = -2; e <= 2; ++e) {
        right = right || ofLevel(pixel(image, static_cast<int>(kW / 2.0 + r) + d, kH / 2 + e));
        below = below || ofLevel(pixel(image, kW / 2 + e, static_cast<int>(kH / 2.0 + r) + d));
      }
    }
    EXPECT_TRUE(right && below) << "ring of L" << level << " at " << r << " px";
    ++checked;
  }
  EXPECT_GT(checked, 0) << "no ring of a size to check";
}

// The foveated method that loses the gaze puts the fovea at the screen's centre: the frames say so,
// and the rings move there with it.
TEST(ViewerFoveation, ALostGazeMovesTheFoveaAndItsRingsToTheScreenCentre) {
  const std::string dir = scratchDir();
  sph_test::ServerProgram server(serverArgs("pbf", "foveated", {"--realtime", "off"}), dir + "/server");
  zmq::context_t context;
  zmq::socket_t gaze(context, zmq::socket_type::pub);
  gaze.set(zmq::sockopt::linger, 0);
  gaze.connect(server.endpoints().gaze);
  std::uint64_t sequence = 0;
  const auto sendGaze = [&] {
    gsph::v1::GazeSample sample;
    sample.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
    sample.set_source_id("test");
    sample.set_sequence(++sequence);
    sample.set_x(0.2f);
    sample.set_y(0.3f);
    sample.set_valid(true);
    sample.set_confidence(1.0f);
    const std::string bytes = sample.SerializeAsString();
    gaze.send(zmq::buffer(bytes), zmq::send_flags::dontwait);
  };
  gsph::v1::Frame tracked, lost;
  ASSERT_TRUE(nextFrame(
      server.endpoints().frames,
      [&](const gsph::v1::Frame& f) {
        sendGaze();
        return f.gaze().mode() == gsph::v1::GAZE_MODE_TRACKING && f.fovea_ring_radii_size() > 0;
      },
      tracked))
      << server.log();
  EXPECT_NEAR(tracked.gaze().x(), 0.2f, 1e-6);
  EXPECT_NEAR(tracked.gaze().y(), 0.3f, 1e-6);
  // No more samples: held for gaze_hold_s, then lost.
  ASSERT_TRUE(nextFrame(
      server.endpoints().frames,
      [](const gsph::v1::Frame& f) { return f.gaze().mode() == gsph::v1::GAZE_MODE_FALLBACK; }, lost))
      << server.log();
  EXPECT_EQ(lost.gaze().x(), 0.5f);
  EXPECT_EQ(lost.gaze().y(), 0.5f);
  ASSERT_EQ(lost.fovea_ring_radii_size(), tracked.fovea_ring_radii_size());
  // At the centre the ring is the exact circle, off it the mean of a stretched one: not the same.
  const int last = lost.fovea_ring_radii_size() - 1;
  EXPECT_GT(lost.fovea_ring_radii(last), 0.0f);
  EXPECT_NE(lost.fovea_ring_radii(last), tracked.fovea_ring_radii(last));
}

TEST(ServerGovernor, OneWarningWhenHeldAtTheCeilingAndOneLineWhenItLeaves) {
  const std::string dir = scratchDir();
  // Every step 40 ms longer than the machine needs: behind real time whatever the machine.
  sph_test::ServerProgram server(serverArgs("pbf", "foveated", {"--slow-step-ms", "40"}), dir + "/server");
  const std::string warning = "real-time governor at its ceiling";
  ASSERT_TRUE(waitUntil([&] { return server.log().find(warning) != std::string::npos; })) << server.log();
  // Held there for many more governor windows (half a second each): still one line.
  gsph::v1::Frame first, later;
  ASSERT_TRUE(nextFrame(
      server.endpoints().frames, [](const auto& f) { return f.step() > 0; }, first));
  ASSERT_TRUE(nextFrame(
      server.endpoints().frames,
      [&](const auto& f) { return f.sim_time() > first.sim_time() + 0.5 && f.periphery_gain() > 0; }, later));
  EXPECT_EQ(later.periphery_gain(), later.periphery_gain_ceiling());
  EXPECT_EQ(count(server.log(), warning), 1u) << server.log();
  gsph::v1::Control surface;
  surface.mutable_set_method()->set_method(gsph::v1::METHOD_SURFACE);
  ASSERT_TRUE(control(server.endpoints().control, surface).ok());
  const std::string left = "real-time governor below its ceiling again";
  ASSERT_TRUE(waitUntil([&] { return server.log().find(left) != std::string::npos; })) << server.log();
  EXPECT_EQ(count(server.log(), warning), 1u);
  EXPECT_EQ(count(server.log(), left), 1u);
}

}  // namespace
