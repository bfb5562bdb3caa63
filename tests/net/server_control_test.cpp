// Every control verb over a real DEALER (and a REQ) socket, with its error cases: each request gets
// one reply echoing its id, errors carry a code, and a refused request changes nothing.
#include <gtest/gtest.h>

#include <limits>
#include <map>

#include "net_test_util.h"

namespace {

// tiny_pool's particle count soon after a start or a reset: 1,000 L1 at the start. No gaze has
// arrived, so the gaze method refines by the surface (the lost-gaze fallback): once a step has
// run, surface particles have split. How many steps run before the reply depends on the load.
void expectFreshTinyPool(const gsph::v1::ServerStatus& status) {
  EXPECT_GE(status.particle_count(), 1000u);
  EXPECT_LE(status.particle_count(), 2000u);
}

using gsph::v1::Control;
using gsph::v1::ControlReply;
using net_test::ControlClient;
using net_test::FrameSubscriber;

struct ControlRun {
  std::unique_ptr<app::Server> server;
  zmq::context_t ctx;
  ControlClient client;
  FrameSubscriber sub;
  explicit ControlRun(sph::Method method = sph::Method::Gaze)
      : server(net_test::startServer(net_test::testOptions(method))),
        client(ctx, server->endpoints().control),
        sub(ctx, server->endpoints().frames) {}

  ControlReply request(const Control& c) {
    auto reply = client.send(c);
    EXPECT_TRUE(reply) << "no reply";
    if (!reply) return {};
    EXPECT_EQ(reply->request_id(), client.lastId());
    EXPECT_EQ(reply->protocol_version(), 1u);
    return *reply;
  }
  ControlReply status() { return request(net_test::statusRequest()); }
  Control setParameters(std::initializer_list<std::pair<const std::string, double>> values) {
    Control c;
    c.mutable_set_parameters();  // present even when empty
    for (const auto& [k, v] : values) (*c.mutable_set_parameters()->mutable_values())[k] = v;
    return c;
  }
  // Each request is refused as a bad parameter, and `kept` still reads as it did (nothing applied).
  void expectBadParameters(std::initializer_list<Control> requests, std::map<std::string, double> kept) {
    for (const Control& bad : requests) {
      const ControlReply r = request(bad);
      EXPECT_FALSE(r.ok());
      EXPECT_EQ(r.error_code(), gsph::v1::ERROR_CODE_BAD_PARAMETER);
      EXPECT_FALSE(r.error().empty());
      for (const auto& [name, value] : kept) EXPECT_DOUBLE_EQ(r.status().parameters().at(name), value) << name;
    }
  }
};

TEST(ServerControl, StatusDescribesTheServer) {
  ControlRun run;
  const ControlReply r = run.status();
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.error_code(), gsph::v1::ERROR_CODE_NONE);
  EXPECT_EQ(r.status().scene(), "tiny_pool");
  EXPECT_EQ(r.status().method(), gsph::v1::METHOD_GAZE);
  expectFreshTinyPool(r.status());
  EXPECT_FALSE(r.status().paused());
  const auto& scenes = r.status().scenes();
  EXPECT_NE(std::find(scenes.begin(), scenes.end(), "tiny_column"), scenes.end());
  EXPECT_DOUBLE_EQ(r.status().parameters().at("gaze_radius"), 0.12);
  EXPECT_DOUBLE_EQ(r.status().parameters().at("publish_hz"), 60.0);
  EXPECT_LT(r.status().gaze_age_ms(), 0.0f) << "no gaze has arrived";
  // The one frame subscriber of this run is counted (XPUB subscriptions).
  const auto end = std::chrono::steady_clock::now() + net_test::kTimeout;
  while (run.status().status().subscribers() != 1 && std::chrono::steady_clock::now() < end) {
    run.sub.next(std::chrono::milliseconds(50));
  }
  EXPECT_EQ(run.status().status().subscribers(), 1u);
}

TEST(ServerControl, PauseStopsTheStepAndResumeRestartsIt) {
  ControlRun run;
  Control pause;
  pause.mutable_pause();
  ASSERT_TRUE(run.request(pause).ok());
  // Frames keep coming while paused, all with the same step.
  auto paused = run.sub.waitFor([](const gsph::v1::Frame& f) { return f.paused(); });
  ASSERT_TRUE(paused);
  for (int i = 0; i < 5; ++i) {
    auto f = run.sub.next();
    ASSERT_TRUE(f);
    EXPECT_TRUE(f->paused());
    EXPECT_EQ(f->step(), paused->step());
  }
  EXPECT_TRUE(run.status().status().paused());
  Control resume;
  resume.mutable_resume();
  ASSERT_TRUE(run.request(resume).ok());
  EXPECT_TRUE(run.sub.waitFor([&](const gsph::v1::Frame& f) { return !f.paused() && f.step() > paused->step(); }));
}

TEST(ServerControl, ResetRestartsTheScene) {
  ControlRun run;
  ASSERT_TRUE(run.sub.waitFor([](const gsph::v1::Frame& f) { return f.step() >= 20; }));
  Control reset;
  reset.mutable_reset();
  const ControlReply r = run.request(reset);
  ASSERT_TRUE(r.ok());
  EXPECT_LT(r.status().step(), 20);
  expectFreshTinyPool(r.status());
}

TEST(ServerControl, LoadSceneByNameOnly) {
  ControlRun run;
  Control load;
  load.mutable_load_scene()->set_scene("tiny_column");
  ControlReply r = run.request(load);
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.status().scene(), "tiny_column");
  EXPECT_EQ(r.status().particle_count(), 500u);
  EXPECT_TRUE(run.sub.waitFor([](const gsph::v1::Frame& f) { return f.scene() == "tiny_column"; }));

  for (const char* bad : {"no_such_scene", "/etc/passwd", "../scenes/dambreak", ""}) {
    load.mutable_load_scene()->set_scene(bad);
    r = run.request(load);
    EXPECT_FALSE(r.ok()) << bad;
    EXPECT_EQ(r.error_code(), gsph::v1::ERROR_CODE_UNKNOWN_SCENE) << bad;
    EXPECT_EQ(r.status().scene(), "tiny_column") << "a refused load changes nothing";
  }
}

TEST(ServerControl, SetMethodSwapsInPlaceOrRestartsForRegular) {
  ControlRun run;
  ASSERT_TRUE(run.sub.waitFor([](const gsph::v1::Frame& f) { return f.step() >= 10; }));
  Control set;
  set.mutable_set_method()->set_method(gsph::v1::METHOD_SURFACE);
  ControlReply r = run.request(set);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.status().method(), gsph::v1::METHOD_SURFACE);
  EXPECT_GE(r.status().step(), 10) << "between adaptive methods the scene keeps running";

  set.mutable_set_method()->set_method(gsph::v1::METHOD_REGULAR);
  r = run.request(set);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.status().method(), gsph::v1::METHOD_REGULAR);
  ASSERT_GE(r.status().level_counts_size(), 2);
  EXPECT_EQ(r.status().level_counts(0), 2000u) << "regular restarts the scene with L0 particles";
  EXPECT_LT(r.status().step(), 10);

  for (int bad : {static_cast<int>(gsph::v1::METHOD_UNSPECIFIED), 99}) {
    set.mutable_set_method()->set_method(static_cast<gsph::v1::Method>(bad));
    r = run.request(set);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.error_code(), gsph::v1::ERROR_CODE_UNKNOWN_METHOD);
    EXPECT_EQ(r.status().method(), gsph::v1::METHOD_REGULAR);
  }
}

TEST(ServerControl, SetPresetRestartsTheSceneWithTheOtherFluid) {
  ControlRun run;
  EXPECT_EQ(run.status().status().preset(), "thesis") << "tiny_pool names the thesis preset";
  ASSERT_TRUE(run.sub.waitFor([](const gsph::v1::Frame& f) { return f.step() >= 10; }));
  Control set;
  set.mutable_set_preset()->set_preset("pbf");
  ControlReply r = run.request(set);
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.status().preset(), "pbf");
  EXPECT_EQ(r.status().scene(), "tiny_pool");
  EXPECT_EQ(r.status().method(), gsph::v1::METHOD_GAZE) << "the method stays";
  EXPECT_LT(r.status().step(), 10) << "the scene restarted";
  expectFreshTinyPool(r.status());

  for (const char* bad : {"water", "", "PBF"}) {
    set.mutable_set_preset()->set_preset(bad);
    r = run.request(set);
    EXPECT_FALSE(r.ok()) << bad;
    EXPECT_EQ(r.error_code(), gsph::v1::ERROR_CODE_UNKNOWN_PRESET) << bad;
    EXPECT_NE(r.error().find("thesis, pbf, dfsph"), std::string::npos) << r.error();
    EXPECT_EQ(r.status().preset(), "pbf") << "a refused preset changes nothing";
  }
  // The chosen preset stays for a reset and for the scenes loaded after it.
  Control reset;
  reset.mutable_reset();
  EXPECT_EQ(run.request(reset).status().preset(), "pbf");
  Control load;
  load.mutable_load_scene()->set_scene("tiny_column");
  r = run.request(load);
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.status().preset(), "pbf");
}

TEST(ServerControl, SetParametersAllOrNothing) {
  ControlRun run;
  ControlReply r = run.request(run.setParameters({{"gaze_radius", 0.1}, {"publish_hz", 30.0}}));
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_DOUBLE_EQ(r.status().parameters().at("gaze_radius"), 0.1);
  EXPECT_DOUBLE_EQ(r.status().parameters().at("publish_hz"), 30.0);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  run.expectBadParameters({run.setParameters({{"no_such_parameter", 1.0}}), run.setParameters({{"gaze_radius", nan}}),
                           run.setParameters({{"gaze_radius", 0.2}, {"publish_hz", 0.0}}),
                           run.setParameters({{"gaze_radius", 0.5}}),  // beyond the ring radius
                           run.setParameters({{"quantized", 0.5}}), run.setParameters({})},
                          {{"gaze_radius", 0.1}, {"publish_hz", 30.0}});
  ASSERT_TRUE(run.request(run.setParameters({{"quantized", 1.0}})).ok());
  EXPECT_TRUE(run.sub.waitFor([](const gsph::v1::Frame& f) {
    return f.encoding() == gsph::v1::POSITION_ENCODING_QUANTIZED16 && f.positions().size() == 6 * f.particle_count();
  }));
}

// Simulation parameters (sph/param_table.h) restart the scene with them, all or nothing.
TEST(ServerControl, SetParametersTakesSimulationParametersAndRestarts) {
  ControlRun run;
  ControlReply r = run.request(run.setParameters({{"pbf_iterations", 3.0}, {"xsph_viscosity", 0.02}}));
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_DOUBLE_EQ(r.status().parameters().at("pbf_iterations"), 3.0);
  EXPECT_DOUBLE_EQ(r.status().parameters().at("xsph_viscosity"), 0.02);
  run.expectBadParameters({run.setParameters({{"pbf_iterations", 2.5}}), run.setParameters({{"pbf_omega", 2.0}}),
                           run.setParameters({{"xsph_viscosity", 0.05}, {"mass_large", 1.0}})},
                          {{"xsph_viscosity", 0.02}, {"pbf_iterations", 3.0}});
  // The old name of a renamed key still sets it.
  r = run.request(run.setParameters({{"cfl", 0.3}}));
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_DOUBLE_EQ(r.status().parameters().at("dfsph_cfl"), 0.3);
}

TEST(ServerControl, MalformedRequestsGetBadRequest) {
  ControlRun run;
  auto r = run.client.sendRaw("\x08\x01 this is not a Control message \xff\xff");
  ASSERT_TRUE(r);
  EXPECT_FALSE(r->ok());
  EXPECT_EQ(r->error_code(), gsph::v1::ERROR_CODE_BAD_REQUEST);

  Control wrong_version = net_test::statusRequest();
  wrong_version.set_protocol_version(7);
  wrong_version.set_request_id(42);
  r = run.client.sendRaw(wrong_version.SerializeAsString());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->error_code(), gsph::v1::ERROR_CODE_BAD_REQUEST);
  EXPECT_EQ(r->request_id(), 42u);

  Control empty;
  empty.set_protocol_version(1);
  r = run.client.sendRaw(empty.SerializeAsString());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->error_code(), gsph::v1::ERROR_CODE_BAD_REQUEST);
  EXPECT_TRUE(run.status().ok()) << "the server still answers";
}

TEST(ServerControl, ReqSocketsAreAnsweredToo) {
  ControlRun run;
  zmq::socket_t req(run.ctx, zmq::socket_type::req);
  req.set(zmq::sockopt::linger, 0);
  req.connect(run.server->endpoints().control);
  Control c = net_test::statusRequest();
  c.set_protocol_version(1);
  c.set_request_id(9);
  req.send(zmq::buffer(c.SerializeAsString()), zmq::send_flags::none);
  zmq::pollitem_t item{req.handle(), 0, ZMQ_POLLIN, 0};
  ASSERT_EQ(zmq::poll(&item, 1, std::chrono::milliseconds(net_test::kTimeout)), 1);
  zmq::message_t msg;
  ASSERT_TRUE(req.recv(msg));
  ControlReply reply;
  ASSERT_TRUE(reply.ParseFromArray(msg.data(), static_cast<int>(msg.size())));
  EXPECT_TRUE(reply.ok());
  EXPECT_EQ(reply.request_id(), 9u);
}

}  // namespace

namespace {

// The foveated method needs an incompressible solver: refused on the thesis's (nothing changes),
// taken on pbf, where frames and the status carry each level's radius and the quality in force.
TEST(ServerControl, FoveatedRunsOnPbfAndSaysItsQuality) {
  ControlRun run;
  Control foveated;
  foveated.mutable_set_method()->set_method(gsph::v1::METHOD_FOVEATED);
  ControlReply r = run.request(foveated);
  EXPECT_FALSE(r.ok()) << "tiny_pool's thesis preset has two size classes";
  EXPECT_EQ(r.error_code(), gsph::v1::ERROR_CODE_BAD_PARAMETER);
  EXPECT_NE(r.error().find("size levels"), std::string::npos) << r.error();
  EXPECT_EQ(r.status().method(), gsph::v1::METHOD_GAZE);

  Control pbf;
  pbf.mutable_set_preset()->set_preset("pbf");
  ASSERT_TRUE(run.request(pbf).ok());
  r = run.request(foveated);
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.status().method(), gsph::v1::METHOD_FOVEATED);
  EXPECT_GE(r.status().quality(), 1.0f);
  EXPECT_GE(r.status().periphery_gain(), 1.0f);
  ASSERT_TRUE(run.sub.waitFor([](const gsph::v1::Frame& f) {
    return f.method() == gsph::v1::METHOD_FOVEATED && f.level_radii_size() == 4 && f.quality() >= 1.0f &&
           f.periphery_gain() >= 1.0f;
  })) << "frames of the foveated method with its levels, quality and periphery gain";
  const std::string line = net_test::statusLineOnce(
      *run.server, [](const std::string& l) { return l.find("over the perceptual budget") != std::string::npos; });
  EXPECT_NE(line.find("over the perceptual budget at most"), std::string::npos)
      << "the status line says how much of the visible water the eye could tell apart: " << line;

  Control thesis;
  thesis.mutable_set_preset()->set_preset("thesis");
  r = run.request(thesis);
  EXPECT_FALSE(r.ok()) << "the thesis's solver cannot run foveated";
  EXPECT_EQ(r.status().preset(), "pbf");
}

}  // namespace
