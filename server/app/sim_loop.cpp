#include "app/sim_loop.h"

#include <fmt/format.h>
#include <omp.h>
#include <pthread.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <thread>
#include <utility>

#include "app/foveation_echo.h"
#include "net/input_validation.h"
#include "sph/checkpoint.h"

namespace app {
namespace {

// The governor's window, and the most periphery gain it may ask for: at 16 the finer levels'
// rings around the gaze are a sixteenth of the eye's (the coarsest level from about 0.06 degrees).
constexpr double kGovernorWindowS = 0.5;
constexpr double kMaxPeripheryGain = 16.0;

// Behind wall time by more than this (a slow step, a scene load), sim time is re-anchored instead of
// running a burst of catch-up steps.
constexpr std::chrono::milliseconds kMaxLag(100);

std::chrono::steady_clock::duration seconds(double s) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(s));
}

}  // namespace

SimLoop::SimLoop(zmq::context_t& context, const SimLoopOptions& options, net::InputMailbox& mailbox,
                 const net::NetLoop& net, const net::RejectionLog& rejections)
    : options_(options),
      mailbox_(mailbox),
      net_(net),
      rejections_(rejections),
      outbox_(context, net.framePipe(), net.replyPipe()),
      encoder_(options.settings.quantized ? net::PositionEncoding::Quantized16 : net::PositionEncoding::Float32,
               options.velocities),
      settings_(options.settings),
      session_(options.scene_dir, options.adaptive_overrides, [this](sph::AdaptiveController& c) { feedGaze(c); }),
      control_target_{session_, settings_, [this](gsph::v1::ServerStatus& s) { fillCounters(s); }},
      pacer_(options.settings.publish_hz, Clock::now()),
      refusal_log_(options.log_interval),
      governor_(1.0, kMaxPeripheryGain) {
  encoder_.setNeighborCounts(options.neighbor_counts);
  session_.usePreset(options.preset);
  session_.useSimParameters(options.sim_parameters);
  // Filling the water and letting fresh incompressible water settle takes a few seconds.
  spdlog::info("loading scene {}: filling the water and letting it settle", options.scene);
  session_.load(options.scene, options.method, /*allow_paths=*/true);
  const sph::Scene& scene = session_.scene();
  spdlog::info("scene {}, preset {}, method {}, {} particles, {} Hz, {}", scene.name, session_.preset(),
               sph::methodName(session_.method()), session_.sim().particles().size(), options.settings.publish_hz,
               options.settings.free_run ? "free-run" : "real time");
  // sph_bench replays a scene's gaze recording; the server takes gaze from the network, but a
  // scene naming a recording that is not there is worth a word.
  if (!scene.gaze_recording.empty() && !std::filesystem::exists(scene.gaze_recording)) {
    spdlog::warn("scene {}: its gaze recording {} does not exist (sph_bench's gaze methods need it)", scene.name,
                 scene.gaze_recording);
  }
  if (!options.load_state.empty()) {
    const sph::CheckpointInfo info =
        sph::loadCheckpoint(session_.sim(), sph::methodName(session_.method()), options.load_state);
    spdlog::info("continuing from {}: step {}, {} particles", options.load_state, info.steps, info.particles);
  }
  net::fromScreenCamera(session_.camera(), camera_msg_);
  camera_msg_.set_viewer_id("scene");
}

SimLoop::~SimLoop() { stop(); }

void SimLoop::start() {
  stop_ = false;
  thread_ = std::thread([this] { run(); });
}

void SimLoop::stop() {
  stop_ = true;
  mailbox_.wake();
  if (thread_.joinable()) thread_.join();
}

void SimLoop::restartClock(Clock::time_point now) {
  anchor_wall_ = now;
  anchor_sim_ = session_.sim().time();
}

SimLoop::Clock::time_point SimLoop::nextStepTime() const {
  const double next_sim = session_.sim().time() + session_.sim().params().time_step;
  return anchor_wall_ + seconds(next_sim - anchor_sim_);
}

void SimLoop::run() {
  pthread_setname_np(pthread_self(), "sph-sim");
  // OpenMP's thread count is per calling thread: set it on the thread that steps.
  omp_set_num_threads(std::max(1, options_.threads));
  Clock::time_point now = Clock::now();
  restartClock(now);
  pacer_ = PublishPacer(settings_.publish_hz, now);
  next_status_ = now + seconds(options_.status_interval_s);
  rate_window_start_ = now;
  governor_.reset(session_.config().foveated_periphery_gain);
  governor_window_start_ = now;
  governor_window_sim_ = session_.sim().time();
  while (!stop_.load()) {
    handleControls();
    pacer_.setRate(settings_.publish_hz);  // a new rate applies from the next frame on
    applyCamera();
    now = Clock::now();
    const bool running = !settings_.paused && !finished_.load();
    // A gaze sample no step has used may start the step up to one dt early, so the frame it refines
    // need not wait out the idle part of the step clock. No step starts more than dt before its
    // time, so sim time leads wall time by less than dt, and the step rate stays the real-time one.
    const Clock::duration dt = seconds(session_.sim().params().time_step);
    const bool early = running && gazeWaiting() && now >= nextStepTime() - dt;
    if (running && (settings_.free_run || now >= nextStepTime() || early)) {
      if (!settings_.free_run && now - nextStepTime() > kMaxLag) restartClock(now);
      const Clock::time_point step_start = Clock::now();
      try {
        session_.step();
      } catch (const std::exception& e) {
        // The library refuses a state it cannot step (a scene whose class masses the adaptive step
        // cannot handle, for example): pause and say so instead of losing the thread.
        spdlog::error("step {} failed, pausing: {}", session_.sim().stepCount(), e.what());
        settings_.paused = true;
      }
      if (options_.slow_step_ms > 0.0) std::this_thread::sleep_for(seconds(options_.slow_step_ms / 1000.0));
      counters_.steps.fetch_add(1);
      ++rate_window_steps_;
      now = Clock::now();
      governor_busy_ += now - step_start;
      // The frame that shows a new gaze sample's refinement goes out now, not at the next tick.
      if (std::exchange(step_used_new_gaze_, false)) pacer_.freshSample();
      if (options_.max_steps > 0 && counters_.steps.load() >= options_.max_steps) {
        publish(now);
        finished_ = true;
        spdlog::info("ran {} steps (--max-steps)", counters_.steps.load());
      }
    }
    govern(now, running);
    if (pacer_.due(now)) publish(now);
    updateRates(now);
    if (options_.status_interval_s > 0.0 && now >= next_status_) {
      refreshStatusLine(now);
      spdlog::info("{}", statusLine());
      next_status_ = now + seconds(options_.status_interval_s);
      gaze_frames_ = gaze_on_water_frames_ = gaze_finest_frames_ = 0;
      worst_over_budget_ = 0.0;
    }
    if (running && settings_.free_run) continue;
    Clock::time_point deadline = pacer_.nextDue();
    if (running) deadline = std::min(deadline, nextStepTime());
    if (running && gazeWaiting()) deadline = std::min(deadline, nextStepTime() - dt);
    if (options_.status_interval_s > 0.0) deadline = std::min(deadline, next_status_);
    mailbox_.waitUntil(deadline);
  }
  refreshStatusLine(Clock::now());
  saveState();
}

void SimLoop::saveState() {
  if (options_.save_state.empty()) return;
  try {
    sph::saveCheckpoint(session_.sim(), sph::methodName(session_.method()), options_.save_state);
    spdlog::info("state at step {} saved to {}", session_.sim().stepCount(), options_.save_state);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    state_saved_ = false;
  }
}

void SimLoop::handleControls() {
  requests_.clear();
  mailbox_.takeControls(requests_);
  for (const net::ControlRequest& request : requests_) {
    ControlEffects effects;
    gsph::v1::ControlReply reply = executeControl(request.control, control_target_, effects);
    reply.mutable_status()->set_client_role(curve::roleName(request.role));
    if (!reply.ok()) {
      // A refusal's error repeats peer text only cut short (control_executor.cpp), and a flood of
      // refusals logs a line per interval, with their count.
      if (const std::uint64_t n = refusal_log_.note()) {
        spdlog::info("refused {} control request(s) (latest: request {}: {})", n, request.control.request_id(),
                     reply.error());
      }
    }
    if (effects.restart_clock) restartClock(Clock::now());
    if (!session_.cameraFromClient()) {
      net::fromScreenCamera(session_.camera(), camera_msg_);  // a new scene brings its own camera
      camera_msg_.set_viewer_id("scene");
    }
    outbox_.sendReply(request, reply);
  }
}

void SimLoop::applyCamera() {
  const std::uint64_t version = mailbox_.poseVersion();
  if (version == applied_pose_version_) return;
  applied_pose_version_ = version;
  net::PoseArrival pose;
  if (!mailbox_.selectedPose(options_.camera_source, pose)) return;
  session_.setCamera(pose.camera, /*from_client=*/true);
  net::fromScreenCamera(pose.camera, camera_msg_);
  camera_msg_.set_viewer_id(pose.viewer_id);
  camera_msg_.set_sequence(pose.sequence);
}

bool SimLoop::gazeWaiting() const {
  net::GazeArrival arrival;
  return sph::refinesGazeCircle(session_.method()) && mailbox_.latestGaze(arrival) && arrival.arrived != last_fed_gaze_;
}

void SimLoop::feedGaze(sph::AdaptiveController& controller) {
  net::GazeArrival arrival;
  sph::GazeInput input;
  if (mailbox_.latestGaze(arrival)) {
    input.present = true;
    input.x = arrival.x;
    input.y = arrival.y;
    input.age_s = std::chrono::duration<double>(Clock::now() - arrival.arrived).count();
    if (arrival.arrived != last_fed_gaze_) {
      last_fed_gaze_ = arrival.arrived;
      step_used_new_gaze_ = true;
    }
    gaze_echo_.has_sample = true;
    gaze_echo_.sample_sequence = arrival.sequence;
    gaze_echo_.sample_bridge_time_us = arrival.bridge_time_us;
    gaze_echo_.source_id = arrival.source_id;
  }
  controller.setGaze(input);
}

void SimLoop::publish(Clock::time_point now) {
  pacer_.published(now);
  if (session_.measureEye()) countFoveatedFrame();
  net::FrameInfo info;
  info.sequence = frame_sequence_;
  info.scene = session_.scene().name;
  info.method = session_.method();
  info.paused = settings_.paused;
  info.steps_per_second = counters_.steps_per_second.load();
  info.quality = static_cast<float>(session_.quality());
  info.periphery_gain = static_cast<float>(session_.peripheryGain());
  info.realtime_ratio = realtime_ratio_.load();
  if (const sph::AdaptiveController* c = session_.controller()) {
    const sph::AdaptiveStats& stats = c->lastStats();
    gaze_echo_.mode = net::toProtoGazeMode(stats.gaze_mode);
    gaze_echo_.x = stats.gaze_x;
    gaze_echo_.y = stats.gaze_y;
    gaze_echo_.age_s = stats.gaze_age_s;
    gaze_echo_.radius = c->config().gaze_radius;
    gaze_echo_.ring_radius = c->config().gaze_ring_radius;
    info.gaze = gaze_echo_;
  }
  info.foveation = foveationEcho(session_, kMaxPeripheryGain);
  info.camera = &camera_msg_;
  encoder_.setEncoding(settings_.quantized ? net::PositionEncoding::Quantized16 : net::PositionEncoding::Float32);
  encoder_.encode(session_.sim(), info);
  // Sequence numbers count frames offered; one the pipe drops shows up as a gap, as any drop does.
  ++frame_sequence_;
  if (outbox_.offerFrame(encoder_.serialize())) {
    counters_.frames_published.fetch_add(1);
  } else {
    counters_.frames_dropped.fetch_add(1);
  }
}

void SimLoop::govern(Clock::time_point now, bool running) {
  const double window = std::chrono::duration<double>(now - governor_window_start_).count();
  // A restarted scene (its clock went back) starts from the configured gain; a pause, free-run or
  // another method leaves the window's figures meaningless: start the window afresh.
  const bool restarted = session_.sim().time() < governor_window_sim_;
  if (restarted) governor_.reset(session_.config().foveated_periphery_gain);
  const bool governed = options_.realtime_governor && running && !settings_.free_run && !restarted &&
                        sph::sizesByAcuity(session_.method());
  if (governed && window < kGovernorWindowS) return;
  if (governed) {
    const double sim_s = session_.sim().time() - governor_window_sim_;
    const double configured = session_.config().foveated_periphery_gain;
    if (configured != governor_.baseGain()) governor_.reset(configured);
    session_.setPeripheryGain(governor_.update(sim_s, window, std::chrono::duration<double>(governor_busy_).count()));
    realtime_ratio_.store(static_cast<float>(governor_.realtimeRatio()));
  } else {
    realtime_ratio_.store(0.0f);
  }
  noteCeiling();
  governor_window_start_ = now;
  governor_window_sim_ = session_.sim().time();
  governor_busy_ = Clock::duration::zero();
}

void SimLoop::noteCeiling() {
  // One line when the governor reaches its ceiling and one when it leaves it: at the ceiling the
  // periphery is as coarse as the governor makes it, and real time is lost anyway.
  const bool at_ceiling = sph::sizesByAcuity(session_.method()) && governor_.atCeiling();
  if (at_ceiling == at_ceiling_) return;
  at_ceiling_ = at_ceiling;
  if (at_ceiling) {
    spdlog::warn(
        "real-time governor at its ceiling: periphery gain {:.1f}, {:.2f} of real time; the foveated "
        "method cannot coarsen further (fewer threads, a smaller scene or a higher q would help)",
        governor_.gain(), governor_.realtimeRatio());
  } else if (sph::sizesByAcuity(session_.method())) {
    spdlog::info("real-time governor below its ceiling again: periphery gain {:.1f}", session_.peripheryGain());
  } else {
    spdlog::info("real-time governor below its ceiling again: the method is {} now",
                 sph::methodName(session_.method()));
  }
}

void SimLoop::countFoveatedFrame() {
  const sph::AdaptiveController* controller = session_.controller();
  if (!sph::sizesByAcuity(session_.method()) || controller == nullptr) return;
  const sph::AdaptiveStats& stats = controller->lastStats();
  ++gaze_frames_;
  gaze_on_water_frames_ += stats.fovea_level >= 0;
  gaze_finest_frames_ += stats.fovea_level == 0;
  if (stats.visible > 0) {
    worst_over_budget_ = std::max(worst_over_budget_, static_cast<double>(stats.over_budget) / stats.visible);
  }
}

void SimLoop::updateRates(Clock::time_point now) {
  const double window = std::chrono::duration<double>(now - rate_window_start_).count();
  if (window < 1.0) return;
  counters_.steps_per_second.store(static_cast<float>(rate_window_steps_ / window));
  refreshStatusLine(now);
  rate_window_steps_ = 0;
  rate_window_start_ = now;
}

void SimLoop::refreshStatusLine(Clock::time_point now) {
  // Rebuilt here, on the thread that owns the session, so other threads can read it any time.
  const sph::ParticleSet& p = session_.sim().particles();
  // The run's levels, finest first.
  const auto counts = p.countByLevel();
  std::string by_level;
  for (int k = 0; k < session_.scene().params.levels; ++k) {
    by_level += fmt::format("{}{} {}", k == 0 ? "" : ", ", sph::levelName(sph::asLevel(k)),
                            counts[static_cast<std::size_t>(k)]);
  }
  net::GazeArrival gaze;
  std::string gaze_text = "no gaze";
  if (mailbox_.latestGaze(gaze)) {
    gaze_text =
        fmt::format("gaze age {:.0f} ms", std::chrono::duration<double, std::milli>(now - gaze.arrived).count());
  }
  std::string line = fmt::format(
      "{} {} {} step {} t={:.2f} s{}: {:.1f} steps/s, {} particles ({}), {} subscribers, "
      "{}, {} frames sent, {} dropped, {} inputs rejected",
      session_.scene().name, session_.preset(), sph::methodName(session_.method()), session_.sim().stepCount(),
      session_.sim().time(), settings_.paused ? " (paused)" : "", counters_.steps_per_second.load(), p.size(), by_level,
      net_.counters().subscriptions.load(), gaze_text, counters_.frames_published.load(),
      counters_.frames_dropped.load(), rejections_.total());
  const float ratio = realtime_ratio_.load();
  if (ratio > 0.0f) line += fmt::format(", {:.2f} of real time", ratio);
  if (sph::sizesByAcuity(session_.method())) {
    line += fmt::format(", q {:.2f}, periphery gain {:.1f}", session_.quality(), session_.peripheryGain());
    // Over the frames published since the last logged status line (the eye is measured once a
    // published frame): how often the gaze fell on visible water, how often the water there was
    // at the finest level, and the largest share of the visible particles over the perceptual
    // budget (q at periphery gain 1) in a frame.
    if (gaze_frames_ > 0) {
      line += fmt::format(", gaze on water in {:.0f} % of frames", 100.0 * gaze_on_water_frames_ / gaze_frames_);
      if (gaze_on_water_frames_ > 0) {
        line += fmt::format(", at {} there in {:.0f} %", sph::levelName(sph::asLevel(0)),
                            100.0 * gaze_finest_frames_ / gaze_on_water_frames_);
      }
      line += fmt::format(", over the perceptual budget at most {:.2f} % of the visible", 100.0 * worst_over_budget_);
    }
    // The last step's particle under the gaze against what the eye resolves there
    // (adaptive/perceptual_budget.h).
    const sph::AdaptiveController* controller = session_.controller();
    if (controller != nullptr && controller->lastStats().fovea_level >= 0) {
      const sph::AdaptiveStats& stats = controller->lastStats();
      line += fmt::format(", under the gaze {} {:.1f}' wide, the eye resolves {:.2f}'",
                          sph::levelName(sph::asLevel(stats.fovea_level)), stats.fovea_width_arcmin,
                          stats.fovea_mar_arcmin);
    }
  }
  if (options_.insecure) line += "; INSECURE: bound beyond loopback without CURVE (--insecure)";
  std::lock_guard lock(status_mutex_);
  status_line_ = std::move(line);
}

std::string SimLoop::statusLine() const {
  std::lock_guard lock(status_mutex_);
  return status_line_.empty() ? std::string("starting") : status_line_;
}

void SimLoop::fillCounters(gsph::v1::ServerStatus& status) const {
  status.set_steps_per_second(counters_.steps_per_second.load());
  status.set_subscribers(static_cast<std::uint32_t>(std::max<std::int64_t>(0, net_.counters().subscriptions.load())));
  net::GazeArrival gaze;
  status.set_gaze_age_ms(
      mailbox_.latestGaze(gaze)
          ? static_cast<float>(std::chrono::duration<double, std::milli>(Clock::now() - gaze.arrived).count())
          : -1.0f);
  status.set_frames_published(counters_.frames_published.load());
  status.set_inputs_rejected(rejections_.total());
  status.set_insecure(options_.insecure);
  status.set_quality(static_cast<float>(session_.quality()));
  status.set_periphery_gain(static_cast<float>(session_.peripheryGain()));
  status.set_realtime_ratio(realtime_ratio_.load());
  const net::FoveationEcho foveation = foveationEcho(session_, kMaxPeripheryGain);
  status.set_periphery_gain_ceiling(foveation.periphery_gain_ceiling);
  status.set_visible_count(foveation.visible);
  status.set_over_budget_count(foveation.over_budget);
  status.set_fovea_width_arcmin(foveation.fovea_width_arcmin);
  status.set_fovea_mar_arcmin(foveation.fovea_mar_arcmin);
}

}  // namespace app
