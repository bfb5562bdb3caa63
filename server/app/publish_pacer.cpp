#include "app/publish_pacer.h"

#include <algorithm>

namespace app {
namespace {

PublishPacer::Clock::duration periodOf(double hz) {
  return std::chrono::duration_cast<PublishPacer::Clock::duration>(std::chrono::duration<double>(1.0 / hz));
}

}  // namespace

PublishPacer::PublishPacer(double hz, Clock::time_point start) : hz_(hz), period_(periodOf(hz)), tick_(start) {}

void PublishPacer::setRate(double hz) {
  if (hz == hz_) return;
  hz_ = hz;
  period_ = periodOf(hz);
  if (last_) tick_ = *last_ + period_;
}

PublishPacer::Clock::time_point PublishPacer::nextDue() const {
  if (!fresh_) return tick_;
  // Two frames in any period at most: the next may follow the last at once, but not the one before it.
  const Clock::time_point early = before_last_ ? *before_last_ + period_ : Clock::time_point::min();
  return std::min(tick_, early);
}

void PublishPacer::published(Clock::time_point now) {
  before_last_ = last_;
  last_ = now;
  if (now >= tick_) {
    // On the clock: keep its cadence, unless the loop fell a whole period behind.
    tick_ += period_;
    if (tick_ <= now) tick_ = now + period_;
  } else {
    tick_ = now + period_;  // an early frame: the next regular one is a period after it
  }
  fresh_ = false;
}

}  // namespace app
