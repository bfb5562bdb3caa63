// The frames socket's reading of subscription messages: "" makes a subscriber, anything else is
// refused and its bytes are held against the limit until libzmq reports them gone.
#include "net/frame_subscriptions.h"

#include <gtest/gtest.h>

#include <string>

namespace {

void feed(net::FrameSubscriptions& s, const std::string& message, bool more = false) {
  s.onMessage(message.data(), message.size(), more);
}

TEST(FrameSubscriptions, TheEmptySubscriptionMakesASubscriber) {
  net::RejectionLog rejections;
  net::FrameSubscriptions s(rejections);
  feed(s, std::string("\x01", 1));
  feed(s, std::string("\x01", 1));
  EXPECT_EQ(s.subscribed(), 2);
  feed(s, std::string("\x00", 1));
  feed(s, std::string("\x00", 1));
  feed(s, std::string("\x00", 1));  // more unsubscriptions than subscriptions: never below zero
  EXPECT_EQ(s.subscribed(), 0);
  EXPECT_EQ(rejections.total(), 0u);
}

TEST(FrameSubscriptions, TopicsAreRefusedAndHeldUntilUnsubscribed) {
  net::RejectionLog rejections;
  net::FrameSubscriptions s(rejections);
  const std::string topic(1000, 't');
  for (int i = 0; i < 16; ++i) feed(s, "\x01" + topic);
  EXPECT_EQ(s.subscribed(), 0) << "a topic subscriber is no frames subscriber";
  EXPECT_EQ(s.heldRefusedBytes(), 16000u);
  EXPECT_FALSE(s.overLimit());
  feed(s, "\x01" + topic + topic);
  EXPECT_TRUE(s.overLimit());
  EXPECT_EQ(rejections.count(net::InputSocket::Subscriptions), 17u);
  // libzmq reports each topic of a peer that leaves as an unsubscription.
  for (int i = 0; i < 17; ++i) feed(s, std::string("\x00", 1) + topic);
  EXPECT_EQ(s.heldRefusedBytes(), 1000u);
  s.forgetRefused();
  EXPECT_EQ(s.heldRefusedBytes(), 0u);
}

TEST(FrameSubscriptions, OtherMessagesAreRejected) {
  net::RejectionLog rejections;
  net::FrameSubscriptions s(rejections);
  feed(s, "");
  feed(s, "\x07junk");
  feed(s, std::string("\x01", 1), /*more=*/true);
  EXPECT_EQ(rejections.count(net::InputSocket::Subscriptions), 3u);
  EXPECT_EQ(s.subscribed(), 0);
  EXPECT_EQ(s.heldRefusedBytes(), 0u);
}

}  // namespace
