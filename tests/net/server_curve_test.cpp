// CURVE on every socket: allowed keys get frames and control by their role, a viewer key
// may ask for status but not pause and its gaze is dropped, and a stranger's key or a plaintext
// client gets nothing and changes nothing.
#include <gtest/gtest.h>

#include <thread>

#include "net_test_util.h"
#include "test_keys.h"

namespace {

using net_test::ControlClient;
using net_test::FrameSubscriber;
using net_test::Publisher;

std::unique_ptr<app::Server> secureServer(const net_test::TestKeys& keys) {
  auto options = net_test::testOptions(sph::Method::Gaze);
  options.net.curve = keys.server;
  options.curve_clients = keys.allowed;
  return net_test::startServer(options);
}

gsph::v1::Control pauseRequest() {
  gsph::v1::Control c;
  c.mutable_pause();
  return c;
}

gsph::v1::GazeSample gazeFrom(const std::string& source, std::uint64_t sequence) {
  gsph::v1::GazeSample g = net_test::gazeSample(0.3, 0.3, sequence);
  g.set_source_id(source);
  return g;
}

TEST(ServerCurve, RolesDecideWhatAnAllowedKeyMayDo) {
  net_test::TestKeys keys;
  auto server = secureServer(keys);
  const net::Endpoints& ep = server->endpoints();
  zmq::context_t ctx;

  FrameSubscriber op_frames(ctx, ep.frames, false, 0, keys.operator_keys);
  FrameSubscriber viewer_frames(ctx, ep.frames, false, 0, keys.viewer_keys);
  ASSERT_TRUE(op_frames.next()) << "an operator key gets frames";
  ASSERT_TRUE(viewer_frames.next()) << "a viewer key gets frames";

  ControlClient op(ctx, ep.control, keys.operator_keys);
  ControlClient viewer(ctx, ep.control, keys.viewer_keys);
  auto status = viewer.send(net_test::statusRequest());
  ASSERT_TRUE(status);
  EXPECT_TRUE(status->ok());
  EXPECT_EQ(status->status().client_role(), "viewer");
  EXPECT_FALSE(status->status().insecure());

  for (gsph::v1::Control forbidden : {pauseRequest(), [] {
                                        gsph::v1::Control c;
                                        (*c.mutable_set_parameters()->mutable_values())["publish_hz"] = 1.0;
                                        return c;
                                      }()}) {
    auto refused = viewer.send(forbidden);
    ASSERT_TRUE(refused);
    EXPECT_FALSE(refused->ok());
    EXPECT_EQ(refused->error_code(), gsph::v1::ERROR_CODE_FORBIDDEN);
    EXPECT_EQ(refused->request_id(), viewer.lastId());
  }
  status = op.send(net_test::statusRequest());
  ASSERT_TRUE(status);
  EXPECT_EQ(status->status().client_role(), "operator");
  EXPECT_FALSE(status->status().paused()) << "the viewer's pause reached the simulation";
  EXPECT_DOUBLE_EQ(status->status().parameters().at("publish_hz"), 60.0);
  auto paused = op.send(pauseRequest());
  ASSERT_TRUE(paused);
  EXPECT_TRUE(paused->ok());
  EXPECT_TRUE(paused->status().paused());
  gsph::v1::Control resume;
  resume.mutable_resume();
  ASSERT_TRUE(op.send(resume));

  // A viewer key's gaze is dropped and counted; an operator's refines the frames.
  Publisher viewer_gaze(ctx, ep.gaze, keys.viewer_keys);
  std::uint64_t sequence = 0;
  const auto end = std::chrono::steady_clock::now() + net_test::kTimeout;
  while (server->rejections().count(net::InputSocket::Gaze) == 0 && std::chrono::steady_clock::now() < end) {
    viewer_gaze.send(gazeFrom("viewer-gaze", ++sequence));
    auto frame = op_frames.next(std::chrono::milliseconds(50));
    if (frame) {
      EXPECT_NE(frame->gaze().source_id(), "viewer-gaze");
    }
  }
  EXPECT_GT(server->rejections().count(net::InputSocket::Gaze), 0u);
  Publisher op_gaze(ctx, ep.gaze, keys.operator_keys);
  EXPECT_TRUE(op_frames.waitFor(
      [](const gsph::v1::Frame& f) {
        EXPECT_NE(f.gaze().source_id(), "viewer-gaze");
        return f.gaze().source_id() == "op-gaze";
      },
      [&] { op_gaze.send(gazeFrom("op-gaze", ++sequence)); }));
}

TEST(ServerCurve, StrangersAndPlaintextClientsGetNothing) {
  net_test::TestKeys keys;
  auto server = secureServer(keys);
  const net::Endpoints& ep = server->endpoints();
  zmq::context_t ctx;
  FrameSubscriber allowed(ctx, ep.frames, false, 0, keys.operator_keys);
  ASSERT_TRUE(allowed.next());

  FrameSubscriber stranger_frames(ctx, ep.frames, false, 0, keys.stranger_keys);
  FrameSubscriber plain_frames(ctx, ep.frames);
  zmq::socket_t stranger_control(ctx, zmq::socket_type::dealer);
  zmq::socket_t plain_control(ctx, zmq::socket_type::dealer);
  net_test::applyKeys(stranger_control, keys.stranger_keys);
  for (zmq::socket_t* s : {&stranger_control, &plain_control}) {
    s->set(zmq::sockopt::linger, 0);
    s->connect(ep.control);
  }
  Publisher stranger_gaze(ctx, ep.gaze, keys.stranger_keys);
  Publisher plain_gaze(ctx, ep.gaze);
  // Both keep trying (libzmq reconnects after every refusal); wait until the server has refused
  // each kind several times and the allowed subscriber has seen many frames meanwhile.
  gsph::v1::Control pause = pauseRequest();
  pause.set_protocol_version(1);
  const std::string pause_bytes = pause.SerializeAsString();
  (void)stranger_control.send(zmq::buffer(pause_bytes), zmq::send_flags::dontwait);
  (void)plain_control.send(zmq::buffer(pause_bytes), zmq::send_flags::dontwait);
  int frames = 0;
  std::uint64_t sequence = 0;
  const auto end = std::chrono::steady_clock::now() + net_test::kTimeout;
  while ((server->keysRefused() < 3 || server->netCounters().handshake_failures.load() < 6 || frames < 30) &&
         std::chrono::steady_clock::now() < end) {
    stranger_gaze.send(gazeFrom("intruder", ++sequence));
    plain_gaze.send(gazeFrom("intruder", ++sequence));
    if (auto frame = allowed.next(std::chrono::milliseconds(50))) {
      ++frames;
      EXPECT_NE(frame->gaze().source_id(), "intruder");
    }
  }
  EXPECT_GE(server->keysRefused(), 3u);
  EXPECT_GE(server->netCounters().handshake_failures.load(), 6u);
  EXPECT_GE(frames, 30);
  EXPECT_FALSE(stranger_frames.next(std::chrono::milliseconds(0))) << "a stranger's key got a frame";
  EXPECT_FALSE(plain_frames.next(std::chrono::milliseconds(0))) << "a plaintext client got a frame";
  zmq::message_t reply;
  EXPECT_FALSE(stranger_control.recv(reply, zmq::recv_flags::dontwait)) << "a stranger's key got a reply";
  EXPECT_FALSE(plain_control.recv(reply, zmq::recv_flags::dontwait)) << "a plaintext client got a reply";
  EXPECT_EQ(server->netCounters().control_requests.load(), 0u) << "a refused client's request arrived";
  EXPECT_EQ(server->netCounters().gaze_samples.load(), 0u) << "a refused client's gaze arrived";
  EXPECT_EQ(server->rejections().total(), 0u) << "nothing a refused client sent got as far as a check";
  ControlClient op(ctx, ep.control, keys.operator_keys);
  auto status = op.send(net_test::statusRequest());
  ASSERT_TRUE(status);
  EXPECT_FALSE(status->status().paused());
}

TEST(ServerCurve, InsecureServersSaySoInEveryStatus) {
  auto options = net_test::testOptions(sph::Method::Regular);
  options.sim.insecure = true;
  auto server = net_test::startServer(options);
  zmq::context_t ctx;
  ControlClient client(ctx, server->endpoints().control);
  auto status = client.send(net_test::statusRequest());
  ASSERT_TRUE(status);
  EXPECT_TRUE(status->status().insecure());
  EXPECT_EQ(status->status().client_role(), "operator") << "without CURVE every peer is an operator";
  const std::string line = net_test::statusLineOnce(*server, [](const std::string& l) { return l != "starting"; });
  EXPECT_NE(line.find("INSECURE"), std::string::npos) << line;
}

}  // namespace
