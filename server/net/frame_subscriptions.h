// What the frames XPUB makes of the subscription messages its peers send. Frames are
// single-part messages with no topic, so the one useful subscription is "" (everything); any other
// is refused: counted, logged at a bounded rate, and not taken for a subscriber.
//
// libzmq still stores every subscription it is sent, one trie node per byte, for as long as its
// connection lives (also with ZMQ_XPUB_MANUAL, which keeps a second trie of them), and no socket
// option bounds how many. So this tally keeps count of the refused bytes libzmq holds (subtracting
// the unsubscriptions it reports, also those of a peer that leaves) and says when the connections
// that sent them must be dropped; the size of one subscription is bounded by the socket's
// ZMQ_MAXMSGSIZE (kMaxSubscriptionBytes). Pure logic: NetLoop feeds it messages and drops peers.
#pragma once

#include <cstddef>
#include <cstdint>

#include "net/rejection_log.h"

namespace net {

// ZMQ_MAXMSGSIZE of the frames socket: a larger subscription disconnects its peer in libzmq. Room for
// a CURVE handshake's largest command (about 300 bytes), which the same limit applies to.
inline constexpr int kMaxSubscriptionBytes = 1024;
// Refused subscription bytes libzmq may hold before their senders are dropped: about 50 bytes of trie
// per byte, so about a MB.
inline constexpr std::size_t kMaxHeldRefusedBytes = 16 * 1024;
// Subscription messages queued from one frames peer (ZMQ_RCVHWM): a subscriber sends one. libzmq files
// each into its trie as it takes it off this queue, so a short queue keeps a flood's lead over the
// check small.
inline constexpr int kSubscriptionQueue = 16;
// What a frames peer may have sent before it counts as hoarding subscriptions (and is dropped): a
// handshake (CURVE's is about 600 bytes), one subscription and heartbeats (below 100 bytes a second
// with CURVE), many times over.
inline constexpr std::uint64_t kSubscriberAllowanceBytes = 8 * 1024;
inline constexpr double kSubscriberAllowanceBytesPerSecond = 256.0;

class FrameSubscriptions {
 public:
  explicit FrameSubscriptions(RejectionLog& rejections) : rejections_(rejections) {}

  // One message the XPUB passed up (ZMQ_XPUB_VERBOSER: every subscribe and unsubscribe, also those
  // libzmq makes for a peer that left). `more`: the message had further parts (already discarded).
  void onMessage(const void* data, std::size_t size, bool more);

  // Subscriptions to "" held: the subscriber count, as long as no peer subscribes twice (NetLoop
  // caps it at the connections the socket has).
  std::int64_t subscribed() const { return subscribed_; }
  std::size_t heldRefusedBytes() const { return held_refused_bytes_; }
  bool overLimit() const { return held_refused_bytes_ > kMaxHeldRefusedBytes; }
  // After every peer was dropped nothing refused is held any more (their unsubscriptions follow).
  void forgetRefused() { held_refused_bytes_ = 0; }

 private:
  RejectionLog& rejections_;
  std::int64_t subscribed_ = 0;
  std::size_t held_refused_bytes_ = 0;
};

}  // namespace net
