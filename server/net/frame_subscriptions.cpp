#include "net/frame_subscriptions.h"

#include <algorithm>
#include <string>

namespace net {

void FrameSubscriptions::onMessage(const void* data, std::size_t size, bool more) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  if (more || size == 0 || bytes[0] > 1) {
    // An XPUB peer may also send ordinary messages; they mean nothing here.
    rejections_.reject(InputSocket::Subscriptions, "not a subscription message");
    return;
  }
  const bool subscribe = bytes[0] == 1;
  const std::size_t topic = size - 1;
  if (topic == 0) {
    if (subscribe) {
      ++subscribed_;
    } else if (subscribed_ > 0) {
      --subscribed_;
    }
    return;
  }
  if (subscribe) {
    held_refused_bytes_ += topic;
    rejections_.reject(InputSocket::Subscriptions,
                       "a " + std::to_string(topic) + "-byte topic (frames have none: subscribe to \"\")");
  } else {
    held_refused_bytes_ -= std::min(held_refused_bytes_, topic);
  }
}

}  // namespace net
